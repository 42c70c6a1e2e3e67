// `skinsim compare A B` without the CLI: A and B are both run directories (`skinsim run
// --out`, holding result.json and frame.png) or both sweep directories (holding
// results.json); what changed between them and what moved (reports/comparison.h).
#pragma once

#include <filesystem>

#include "reports/comparison.h"

namespace skinsim::driver {

// Throws io::InputError naming the file or directory at fault (missing, not a run or sweep
// directory, corrupt), and UserError when A and B are of different kinds. With `out_dir` (not
// empty), writes difference images, crops and the colour bar there and links A's and B's
// frames relative to it.
reports::Comparison compare_outputs(const std::filesystem::path& a, const std::filesystem::path& b,
                                    const reports::Tolerances& tolerances,
                                    const std::filesystem::path& out_dir);

// `path` relative to `dir` (as a page in `dir` links it), or as given when `dir` is empty.
std::string link_from(const std::filesystem::path& dir, const std::filesystem::path& path);

// Two sweep directories (sweep_compare.cpp): configurations matched by id.
reports::Comparison compare_sweeps(const std::filesystem::path& a, const std::filesystem::path& b,
                                   const reports::Tolerances& tolerances,
                                   const std::filesystem::path& out_dir);

}  // namespace skinsim::driver
