// Sensitivity of the frame time to each uncertain profile figure.
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gpu_model/device_profile.h"
#include "sim/counters.h"

namespace skinsim::gpu_model {

struct SensitivityRow {
  std::string figure;  // dotted path, e.g. "gpu.clock_mhz"
  std::string unit;
  Confidence confidence = Confidence::kLow;
  double value_min = 0.0;
  double value_base = 0.0;
  double value_max = 0.0;
  // Frame time with the figure at min / base / max. min and max are empty when the figure
  // changes what the emulator counts and no recount was supplied.
  std::optional<double> frame_ms_min;
  double frame_ms_base = 0.0;
  std::optional<double> frame_ms_max;
  bool needs_recount = false;  // the figure affects the counters (see FigureSpec)

  // |ms @max - ms @min|: how far the figure's range alone moves the frame (empty without both).
  std::optional<double> swing_ms() const {
    if (!frame_ms_min || !frame_ms_max) return std::nullopt;
    return std::abs(*frame_ms_max - *frame_ms_min);
  }
};

// Re-runs the emulator for a varied profile and returns that frame's pass counters.
using Recount = std::function<std::vector<sim::PassCounters>(const DeviceProfile&)>;

// One row per figure that has a range, in profile order. Figures that the emulator's counters
// depend on (texture cache size/line/ways, tile size) are evaluated through `recount` when
// given; without it their rows carry only the base time. Deterministic.
std::vector<SensitivityRow> sensitivity(const std::vector<sim::PassCounters>& passes,
                                        const DeviceProfile& profile, const Recount& recount = {});

// The frame time over the profile's uncertain figures together: the cost model evaluated at
// the corner of the figures' box where the frame is fastest, and where it is slowest. Each
// figure's end is picked from its own one-at-a-time row (the end that lowers, or raises, the
// frame time), then all are set at once, so the range includes how the figures compound (two
// slow units on one pass). Figures that change the emulator's counters (texture cache, tile
// size) need a re-render per end and are left out (`left_out` counts them): the range is the
// cost model's uncertainty for the counted work, not the emulator's.
struct FrameMsRange {
  double low = 0.0;
  double base = 0.0;
  double high = 0.0;
  int figures = 0;   // uncertain figures included
  int left_out = 0;  // uncertain figures that need a re-render, not included
};
FrameMsRange frame_ms_range(const std::vector<sim::PassCounters>& passes,
                            const DeviceProfile& profile);

}  // namespace skinsim::gpu_model
