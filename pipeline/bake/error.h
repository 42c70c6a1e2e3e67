// User-facing error of the bakers: the message names the parameter or file at fault.
#pragma once

#include <stdexcept>
#include <string>

#include "util/user_error.h"

namespace skinsim::bake {

class BakeError : public UserError {
 public:
  using UserError::UserError;
};

}  // namespace skinsim::bake
