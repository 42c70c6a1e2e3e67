// Metric values as people read them: ms with three decimals, bytes in MB, counts whole.
#pragma once

#include <string>

namespace skinsim::budget {

// The value of `metric` with its unit, e.g. "5.357 ms", "27.36 MB", "38.82 dB".
std::string format_value(const std::string& metric, double value);
// A signed difference in the metric's unit, e.g. "+0.412 ms".
std::string format_delta(const std::string& metric, double delta);
// A relative change, e.g. "+8.1%" ("n/a" when the reference is zero).
std::string format_change(double from, double to);

}  // namespace skinsim::budget
