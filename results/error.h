// User-facing error of the result model: the message names the file and field at fault.
#pragma once

#include "util/user_error.h"

namespace skinsim::results {

class ResultsError : public UserError {
 public:
  using UserError::UserError;
};

}  // namespace skinsim::results
