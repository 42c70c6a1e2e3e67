// The one exception type the reports module throws for user-facing errors (bad results.json,
// unwritable output directory, no X display for charts). Messages name the file/field at fault.
#pragma once

#include <stdexcept>
#include <string>

#include "util/user_error.h"

namespace skinsim::reports {

class ReportError : public UserError {
 public:
  using UserError::UserError;
};

}  // namespace skinsim::reports
