// The numbers of a run's result.json (or of a sweep configuration's row) by name, and which of
// them moved between two runs beyond their tolerance.
//
// Names are paths: "timing.frame_ms", "counters.skin_shade.renderer.fragments_shaded",
// "timing.passes.blur_h#2.ms" (array elements by their "name", repeats numbered from the
// second; elements without one by index). The first segment picks the kind: "counters" and
// "technique" are emulator counts ("counter"), "quality" image metrics ("quality"), the rest
// (timing, sensitivity) the cost model's output ("modelled").
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "reports/comparison.h"

namespace skinsim::driver {

using NamedValues = std::map<std::string, double>;

// Every number in `j` under its path, except the "config" object (settings, not results).
NamedValues numeric_values(const nlohmann::json& j);

// Compares every value in `a` or `b` and sets `diff`'s frame times ("timing.frame_ms"),
// values_compared and moved: those in one only or beyond the tolerance of their kind, sorted by
// |relative change|, largest first, then by name.
void compare_values(const NamedValues& a, const NamedValues& b,
                    const reports::Tolerances& tolerances, reports::ConfigDiff& diff);

}  // namespace skinsim::driver
