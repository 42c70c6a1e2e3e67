// User-facing errors of the cost model. Each message names the file (profiles) or the pass
// and field (counters) at fault.
#pragma once

#include <stdexcept>
#include <string>

#include "util/user_error.h"

namespace skinsim::gpu_model {

// Base of every error this module throws.
class Error : public UserError {
 public:
  using UserError::UserError;
};

// A device profile could not be found, parsed or validated.
class ProfileError : public Error {
 public:
  using Error::Error;
};

// Pass counters are inconsistent with themselves or with the device profile.
class CounterError : public Error {
 public:
  using Error::Error;
};

}  // namespace skinsim::gpu_model
