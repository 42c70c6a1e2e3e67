// The truth in a sweep's report.html (`sweep --truth`, docs/validation.md): the "Judged by
// truth" section (how the truth image is encoded, its noise floor, per group whether the
// recommendation and the visibility verdicts stay when the truth judges, and whether this
// truth can tell the configurations apart at all), and each group's truth image for the
// slider and the crops.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "results/sweep_table.h"

namespace skinsim::driver {

// The samples a truth rendered with `samples` would need for its noise floor's FLIP
// (`floor_flip`, two seeds' difference) to fall below `spread` (how far apart the
// configurations' FLIP against it lie): an estimate, taking the noise, and the floor's FLIP
// with it, to fall as 1 / sqrt(samples). None when `spread` is not above 0 (no sample count
// separates equal figures).
std::optional<double> samples_to_separate(double floor_flip, double spread, int samples);

// The section's HTML, from judge_sweep_with_truth's result (truth_sweep.h) and the table it
// added its truth_* columns to.
std::string truth_report_section(const results::SweepTable& table, const nlohmann::json& judged);

// Per group, the path of its truth image in the sweep directory (judged's "image").
std::map<std::string, std::string> truth_report_images(const nlohmann::json& judged);

}  // namespace skinsim::driver
