// Errors of the cost model. Each message names the file (profiles) or the pass and field
// (counters) at fault.
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

// Pass counters are inconsistent with themselves or with the device profile. Counters come
// only from the emulator, so this is a bug in skinsim, not bad input: it is no UserError, and
// `skinsim` reports it as an internal error (exit 3).
class CounterError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

}  // namespace skinsim::gpu_model
