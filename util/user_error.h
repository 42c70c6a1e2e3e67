// The one base class of errors a user can fix: a bad file, field, option or value. The
// message names what is at fault; `skinsim` prints it and exits with status 2. Anything else
// that escapes a command is a bug in skinsim and is reported as an internal error (main.cpp).
#pragma once

#include <stdexcept>
#include <string>

namespace skinsim {

class UserError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace skinsim
