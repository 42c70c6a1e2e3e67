// User-facing error of the bakers: the message names the parameter or file at fault.
#pragma once

#include <stdexcept>
#include <string>

namespace skinsim::bake {

class BakeError : public std::runtime_error {
 public:
  explicit BakeError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace skinsim::bake
