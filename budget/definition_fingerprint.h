// A fingerprint of what a budget measures (device, scene, resolution and every pipeline knob),
// stored in its baseline entry so `skinsim check` can warn when the budget was edited after
// the baseline was recorded and the comparison is no longer like for like.
#pragma once

#include <filesystem>
#include <string>

#include "budget/budget_file.h"

namespace skinsim::budget {

// Paths are taken relative to the budget file's directory, so the fingerprint does not depend
// on the directory `skinsim` runs in. Limits and target_fps are left out: they change how a
// frame is judged, not what is measured.
std::string definition_fingerprint(const Budget& budget, const std::filesystem::path& budget_file);

}  // namespace skinsim::budget
