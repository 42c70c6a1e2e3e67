// Where a pixel's samples lie under multisampling: the standard sample positions that
// Direct3D (D3D11_STANDARD_MULTISAMPLE_PATTERN) and Vulkan (the spec's "Standard sample
// locations" table, used when standardSampleLocations is true) both define for 2 and 4
// samples. Vulkan gives them from the pixel's top-left corner, y down, as the emulator's
// screen space is: 2x (0.75, 0.75), (0.25, 0.25); 4x (0.375, 0.125), (0.875, 0.375),
// (0.125, 0.625), (0.625, 0.875). Every position is a multiple of 1/16 pixel, so it is exact
// in the rasteriser's 8-bit sub-pixel grid. At 1x the one sample is the pixel centre.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "sim/triangle_setup.h"

namespace skinsim::sim {

constexpr int kMaxSamples = 4;

struct SamplePattern {
  int count = 1;
  // Offset of each sample from the pixel centre, in sub-pixel units.
  std::array<std::int64_t, kMaxSamples> dx{};
  std::array<std::int64_t, kMaxSamples> dy{};
  // The largest |dx| or |dy|: how far past a pixel centre a sample can reach, which widens
  // a triangle's bounding box and a tile's binning test.
  std::int64_t reach = 0;
};

// The standard pattern of 1, 2 or 4 samples; std::invalid_argument for any other count.
inline const SamplePattern& sample_pattern(int samples) {
  constexpr std::int64_t k = kSubpixelOne / 16;  // the patterns' 1/16-pixel unit
  static const SamplePattern one{1, {0, 0, 0, 0}, {0, 0, 0, 0}, 0};
  static const SamplePattern two{2, {4 * k, -4 * k, 0, 0}, {4 * k, -4 * k, 0, 0}, 4 * k};
  static const SamplePattern four{
      4, {-2 * k, 6 * k, -6 * k, 2 * k}, {-6 * k, -2 * k, 2 * k, 6 * k}, 6 * k};
  switch (samples) {
    case 1:
      return one;
    case 2:
      return two;
    case 4:
      return four;
    default:
      throw std::invalid_argument("MSAA sample count must be 1, 2 or 4, got " +
                                  std::to_string(samples));
  }
}

}  // namespace skinsim::sim
