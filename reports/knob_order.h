// Ordering knob values the way a reader expects: "8x32" < "32x128" < "64x256", "0.25" < "1".
#pragma once

#include <string>

namespace skinsim::reports {

// Compares the numbers embedded in a and b as sequences (e.g. "32x128" -> {32, 128}); if those
// are equal or either has none, falls back to plain string order.
bool knob_value_less(const std::string& a, const std::string& b);

}  // namespace skinsim::reports
