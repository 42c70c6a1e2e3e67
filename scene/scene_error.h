// The scene module's user-facing error: bad files and bad options. The message starts with
// the file path (or option name) at fault and says what is wrong.
#pragma once

#include <stdexcept>
#include <string>

namespace skinsim::scene {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace skinsim::scene
