// `skinsim compare`'s terminal output: what changed, what moved (largest first), the frames'
// verdicts, and the result line that matches the exit status.
#pragma once

#include <cstddef>
#include <string>

#include "reports/comparison.h"

namespace skinsim::reports {

// What "no change" means: only what result.json / results.json record is compared.
inline constexpr const char* kNoChangeText =
    "no recorded setting differs (the knobs, device and scene name; scene build options such "
    "as --head-triangles or --texture-size are not recorded)";

// At most `max_values` moved values per run (compare.json lists all of them).
std::string format_comparison(const Comparison& c, std::size_t max_values = 25);

// "+12.3%", "-0.4%", "from 0", "only in A", "only in B".
std::string change_text(const ValueDelta& d);

// "2.070 ms -> 1.809 ms (-12.6%)", "2.070 ms, unchanged", or "-" without frame times.
std::string frame_time_text(const ConfigDiff& d);

// "visibly different: FLIP mean 0.012, ..." for the frames of one run or configuration.
std::string image_verdict_text(const ImageDiff& d);

// "identical", "1234 px differ (largest 0.120)", "different sizes (32x128 vs 8x32)",
// "only in A", "only in B".
std::string image_change_text(const ImageChange& c);

// The verdict alone, for one row of a table: "visibly different (6675 px above 0.10)".
std::string image_verdict_short(const ImageDiff& d);

// "counters exact, modelled values within 0.1%, quality metrics within 0.1%".
std::string tolerances_text(const Tolerances& t);

}  // namespace skinsim::reports
