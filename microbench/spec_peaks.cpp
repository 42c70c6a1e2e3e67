#include "microbench/spec_peaks.h"

#include <fmt/format.h>

namespace skinsim::microbench {

SpecPeak texel_fill_peak(const gpu_model::DeviceProfile& p) {
  const double tmus = p.tmus_per_core.value * p.cores.value;
  const double per_clock = p.bilinear_per_tmu_clock.value;
  return {
      tmus * per_clock * p.clock_mhz.value,
      fmt::format("{:g} TMUs x {:g} bilinear/clk x {:g} MHz", tmus, per_clock, p.clock_mhz.value)};
}

SpecPeak alu_peak_gflops(const gpu_model::DeviceProfile& p) {
  const double pipes = p.pipes_per_core.value * p.cores.value;
  return {pipes * kFlopPerVectorMad * p.clock_mhz.value * 1e-3,
          fmt::format("{:g} pipes x {:g} FLOP/clk x {:g} MHz", pipes, kFlopPerVectorMad,
                      p.clock_mhz.value)};
}

SpecPeak tiler_peak(const gpu_model::DeviceProfile& p) {
  const double per_clock = p.tiler_triangles_per_clock_per_core.value;
  return {per_clock * p.cores.value * p.clock_mhz.value,
          fmt::format("{:g} tri/clk/core x {:g} cores x {:g} MHz", per_clock, p.cores.value,
                      p.clock_mhz.value)};
}

SpecPeak achievable_bandwidth(const gpu_model::DeviceProfile& p) {
  return {p.dram_peak_gb_per_s.value * p.dram_achievable_fraction.value,
          fmt::format("{:g} GB/s peak x {:g} achievable", p.dram_peak_gb_per_s.value,
                      p.dram_achievable_fraction.value)};
}

}  // namespace skinsim::microbench
