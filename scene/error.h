// The scene module's user-facing error: bad files and bad options. The message starts with
// the file path (or option name) at fault and says what is wrong.
#pragma once

#include <stdexcept>
#include <string>

#include "util/user_error.h"

namespace skinsim::scene {

class SceneError : public UserError {
 public:
  using UserError::UserError;
};

}  // namespace skinsim::scene
