// `sweep --truth` (docs/validation.md): every configuration of a finished sweep judged by the
// path-traced truth of its group's view beside the reference's figures, and, per group, whether
// the recommendation and the visibility verdicts stay the same when the truth judges instead of
// the reference.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "driver/truth/truth_judge.h"
#include "results/sweep_table.h"

namespace skinsim::driver {

// The folder of a sweep directory that holds the truth images.
inline constexpr const char* kTruthImageDir = "truth";

// The truth of one group's view: `row` is one of its configurations, its frame width x height.
using GroupTruth = std::function<Truth(const results::ConfigResult& row, int width, int height)>;

// Adds to each row's quality its figures against its group's truth (frame.png and the
// reference's skin mask from `out_dir`): truth_psnr_skin, truth_ssim_skin, truth_flip_skin,
// truth_visible_skin_pct/px, truth_visible_skin (1 or 0), the same over the frame (…_frame),
// and truth_floor_flip_skin/_frame, the truth's noise floor (absent when not measured); a PSNR
// is absent where it is infinite (a frame identical to the truth), as results.json holds
// finite numbers.
// Writes each group's truth image (as its frames are seen: truth_image.h display_image) to
// out_dir/truth/g<N>.png, N counting the groups in the rows' order.
// Returns, for results.json's "truth", per group: where its truth came from, its image, its
// noise floor, the configuration recommended when the reference judges and when the truth
// does, and the configurations whose verdict "visibly different" changes.
nlohmann::json judge_sweep_with_truth(results::SweepTable& table, const std::string& out_dir,
                                      const GroupTruth& truth_of);

// "ipad4, 64x48: the recommendation stays scale 0.5 (…); 2 of 2 visibility verdicts stay":
// one line per group of judge_sweep_with_truth's result.
std::vector<std::string> truth_sweep_lines(const nlohmann::json& judged);

}  // namespace skinsim::driver
