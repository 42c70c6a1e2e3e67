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

// Throws BakeError("<params>.<field> must be <rule>, got <value>") unless `ok`.
inline void require_param(bool ok, const std::string& params, const std::string& field,
                          const std::string& rule, double value) {
  if (!ok) {
    throw BakeError(params + "." + field + " must be " + rule + ", got " + std::to_string(value));
  }
}

}  // namespace skinsim::bake
