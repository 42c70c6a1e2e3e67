// Consistency checks of emulator counters before the model uses them.
#pragma once

#include "gpu_model/device_profile.h"
#include "sim/counters.h"

namespace skinsim::gpu_model {

// Throws CounterError naming the pass and the field that disagrees.
void check_counters(const sim::PassCounters& pass, const DeviceProfile& profile);

}  // namespace skinsim::gpu_model
