// User-facing error of the micro-benchmarks: a bad option, named in the message.
#pragma once

#include <stdexcept>

#include "util/user_error.h"

namespace skinsim::microbench {

class MicrobenchError : public UserError {
 public:
  using UserError::UserError;
};

}  // namespace skinsim::microbench
