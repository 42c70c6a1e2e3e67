// What every micro-benchmark needs: the emulated GPU configured from the device profile,
// the options, and a way to run a pass and time it with the cost model.
#pragma once

#include <string>

#include "gpu_model/device_profile.h"
#include "microbench/microbench.h"
#include "microbench/spec_peaks.h"
#include "sim/gpu.h"

namespace skinsim::microbench {

struct MeasuredPass {
  sim::PassCounters counters;
  gpu_model::PassTiming timing;
};

class BenchContext {
 public:
  BenchContext(const gpu_model::DeviceProfile& profile, const MicrobenchOptions& options);

  const gpu_model::DeviceProfile& profile() const { return profile_; }
  const MicrobenchOptions& options() const { return options_; }
  double pixels() const { return static_cast<double>(options_.width) * options_.height; }

  // Runs `pass` on the emulated GPU and estimates its time on the device.
  MeasuredPass run(const sim::RenderPassDesc& pass);

 private:
  const gpu_model::DeviceProfile& profile_;
  const MicrobenchOptions& options_;
  sim::Gpu gpu_;
};

// A result row: `work` units done by the pass (in the unit of `peak`, per second once divided
// by the pass time), e.g. texels / 1e6 for Mtexel/s.
MicrobenchResult make_result(std::string name, std::string unit, double work, const SpecPeak& peak,
                             MeasuredPass measured, std::string shows);

}  // namespace skinsim::microbench
