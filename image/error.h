// User-facing error of the image library: the message names the file or image at fault.
#pragma once

#include "util/user_error.h"

namespace skinsim::image {

class ImageError : public UserError {
 public:
  using UserError::UserError;
};

}  // namespace skinsim::image
