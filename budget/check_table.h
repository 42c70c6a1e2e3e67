// The pass/fail table `skinsim check` prints: one row per limit.
#pragma once

#include <string>

#include "budget/check.h"

namespace skinsim::budget {

// Columns: budget, metric, limit, measured, margin, result; then each failure's message
// and a summary line.
std::string format_check_table(const CheckReport& report);

}  // namespace skinsim::budget
