// The comparison panel of each recommendation: the windows of the frame where the recommended
// configuration differs most from the reference and from the group's best configuration,
// cut out of the reference (and, with `sweep --truth`, the path-traced truth), the best frame,
// the recommended frame and their amplified differences, at 1:1 and magnified 4x, written to
// compare/ in the sweep directory.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "reports/recommendation.h"
#include "results/sweep_table.h"

namespace skinsim::driver {

// Writes the crops and returns one panel per recommendation with a chosen configuration.
// `over_skin`: windows are found in the FLIP error over the reference's skin mask.
// `truth_images`: per group, its truth image in the sweep directory (`sweep --truth`): the
// crops then show it and the recommended frame's difference from it too.
std::vector<results::ComparisonPanel> write_comparison_panels(
    const results::SweepTable& table, const std::vector<reports::Recommendation>& recommendations,
    const std::filesystem::path& sweep_dir, bool over_skin,
    const std::map<std::string, std::string>& truth_images = {});

}  // namespace skinsim::driver
