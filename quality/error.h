// User-facing error of the quality module: the message names the image, mask or field at fault.
#pragma once

#include <stdexcept>
#include <string>

namespace skinsim::quality {

class QualityError : public std::runtime_error {
 public:
  explicit QualityError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace skinsim::quality
