// `compare A B --truth` (docs/validation.md): two runs' frames judged by one truth, beside
// what `compare` says of them against each other. `cached` takes the truth both runs were
// judged with (`run --truth cached`: the key in their result.json), from the truth store, or
// with a named TruthChoice the same view's truth of those samples and seeds.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "driver/truth/truth_judge.h"

namespace skinsim::driver {

// {"truth", "noise_floor", "a", "b", "closer"}: each run's frame against the truth (over the
// skin of A's reference when it has one), and which is closer by FLIP ("a", "b" or "same").
// Throws UserError naming the option and run when A or B is not a run directory, their frames
// differ in size, `cached` finds no key in a run's result.json, the two keys differ, or the
// store no longer holds that truth intact (or holds no truth of a named choice:
// missing_named_truth); and as truth_file for a file.
nlohmann::json compare_with_truth(const std::filesystem::path& a, const std::filesystem::path& b,
                                  const std::string& spec, const TruthChoice& choice);

// The lines `compare` prints of compare_with_truth's result.
std::vector<std::string> truth_compare_lines(const nlohmann::json& judged);

}  // namespace skinsim::driver
