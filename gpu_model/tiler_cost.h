// Cost of the tiler (TA) stage of a pass: vertex shading, triangle setup, binning and the
// parameter-buffer write.
#pragma once

#include "gpu_model/device_profile.h"
#include "gpu_model/timing.h"
#include "sim/counters.h"

namespace skinsim::gpu_model {

TilerTiming estimate_tiler(const sim::PassCounters& pass, const DeviceProfile& profile);

// Parameter-buffer bytes the TA writes for the pass.
double parameter_write_bytes(const sim::PassCounters& pass, const DeviceProfile& profile);

}  // namespace skinsim::gpu_model
