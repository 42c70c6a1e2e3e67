// Bad input to the budget checker: a malformed budget file, an unknown device, pass or
// metric, a missing baseline. The message names the file and line at fault.
#pragma once

#include <stdexcept>

namespace skinsim::budget {

class BudgetError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace skinsim::budget
