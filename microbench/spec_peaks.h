// The spec-sheet peaks the micro-benchmarks are compared with, derived from the device
// profile's figures (hardware.md): what the hardware could do with every unit busy.
#pragma once

#include <string>

#include "gpu_model/device_profile.h"

namespace skinsim::microbench {

struct SpecPeak {
  double value = 0.0;
  std::string basis;  // the formula with the profile's numbers, for the report
};

// Bilinear texel fetches per second, in Mtexel/s: TMUs per core x cores x bilinear
// quads per TMU per clock x clock.
SpecPeak texel_fill_peak(const gpu_model::DeviceProfile& profile);

// FP32 GFLOPS: cores x USSE pipes x one vec4 multiply-add (8 FLOP) per pipe per clock x
// clock (hardware.md: ~77 GFLOPS for SGX554MP4 at 300 MHz).
SpecPeak alu_peak_gflops(const gpu_model::DeviceProfile& profile);
constexpr double kFlopPerVectorMad = 8.0;  // 4 lanes x (multiply + add)

// Triangle setup rate of the tiler, in Mtri/s: triangles per clock per core x cores x clock.
SpecPeak tiler_peak(const gpu_model::DeviceProfile& profile);

// Achievable DRAM bandwidth, in GB/s (1e9 bytes): peak x achievable fraction.
SpecPeak achievable_bandwidth(const gpu_model::DeviceProfile& profile);

}  // namespace skinsim::microbench
