// User-facing error of the micro-benchmarks: a bad option, named in the message.
#pragma once

#include <stdexcept>

namespace skinsim::microbench {

class MicrobenchError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace skinsim::microbench
