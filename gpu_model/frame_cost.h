// Cost of a frame: its passes in a two-stage tiler (TA) / renderer (3D) pipeline.
#pragma once

#include <vector>

#include "gpu_model/device_profile.h"
#include "gpu_model/timing.h"
#include "sim/counters.h"

namespace skinsim::gpu_model {

// Passes in submission order. The TA of pass i+1 runs while the 3D renders pass i, as on
// the hardware (hardware.md); see docs/cost-model.md for the schedule.
FrameTiming estimate_frame(const std::vector<sim::PassCounters>& passes,
                           const DeviceProfile& profile);

// The pipeline schedule of already-estimated passes (exposed for tests and reports).
std::vector<PassSlot> pipeline_schedule(const std::vector<PassTiming>& passes);

}  // namespace skinsim::gpu_model
