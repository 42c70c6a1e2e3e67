// What each configuration of a sweep looks like next to the others it can be compared with:
// rows are grouped by device and reference (resolution, light, framing), and every row's frame
// is compared (FLIP over the reference's skin mask) with the best configuration of its own
// technique in its group ("finest": what its knob values cost) and with the group's best over
// every technique (what a recommendation gives up). The comparisons are cached in
// configs/compare/, keyed by both frames' bytes, so a resumed or merged sweep reuses them.
#pragma once

#include <filesystem>

#include "driver/sweep/sweep_spec.h"
#include "results/sweep_table.h"

namespace skinsim::driver {

// Sets every row's group ("ipad4, 2048x1536", plus the swept light and framing knobs that
// shape the reference), vs_finest and vs_best. `metric` picks the best rows (lower is better;
// reports::recommend_metric). Rows whose images are missing keep no comparison.
void add_comparisons(const SweepSpec& spec, results::SweepTable& table,
                     const std::filesystem::path& sweep_dir, const std::string& metric);

// configs/compare/<id>_vs_<other>.json, relative to the sweep directory.
std::string comparison_cache_path(const std::string& id, const std::string& other);

}  // namespace skinsim::driver
