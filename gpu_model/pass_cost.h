// Cost of one render pass: tiler (TA) stage, tiles list-scheduled over the 3D cores, DRAM.
#pragma once

#include "gpu_model/device_profile.h"
#include "gpu_model/timing.h"
#include "sim/counters.h"

namespace skinsim::gpu_model {

// Throws CounterError when the counters are inconsistent (tile grid, draw indices, tile sums
// that disagree with pass totals) or were produced for another tile size or core count.
PassTiming estimate_pass(const sim::PassCounters& pass, const DeviceProfile& profile);

}  // namespace skinsim::gpu_model
