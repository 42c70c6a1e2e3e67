// User-facing error of the quality module: the message names the image, mask or field at fault.
#pragma once

#include <stdexcept>
#include <string>

#include "util/user_error.h"

namespace skinsim::quality {

class QualityError : public UserError {
 public:
  using UserError::UserError;
};

}  // namespace skinsim::quality
