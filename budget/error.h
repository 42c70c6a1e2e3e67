// Bad input to the budget checker: a malformed budget file, an unknown device, pass or
// metric, a missing baseline. The message names the file and line at fault.
#pragma once

#include <stdexcept>

#include "util/user_error.h"

namespace skinsim::budget {

class BudgetError : public UserError {
 public:
  using UserError::UserError;
};

}  // namespace skinsim::budget
