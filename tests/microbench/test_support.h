// Shared helpers of the micro-benchmark tests: shipped profiles and a lookup by name.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gpu_model/profile_loader.h"
#include "microbench/microbench.h"
#include "tests/test_paths.h"

namespace skinsim::microbench::testing {

inline const std::string kDataDir = test_paths::kDataDir;
inline const std::vector<std::string> kShippedDevices = {"ipad4", "ipad3", "iphone5"};

inline gpu_model::DeviceProfile profile(const std::string& name) {
  return gpu_model::load_device_profile(name, kDataDir);
}

// Modest size keeps the suite fast; every benchmark still covers many tiles per core.
inline MicrobenchOptions test_options() {
  MicrobenchOptions o;
  o.width = 512;
  o.height = 384;
  return o;
}

inline const MicrobenchResult& find(const std::vector<MicrobenchResult>& results,
                                    const std::string& name) {
  for (const MicrobenchResult& r : results) {
    if (r.name == name) return r;
  }
  ADD_FAILURE() << "no result named " << name;
  static const MicrobenchResult kMissing;
  return kMissing;
}

// Simulated rates may equal a peak only up to floating-point rounding.
constexpr double kPeakSlack = 1.0 + 1e-9;

}  // namespace skinsim::microbench::testing
