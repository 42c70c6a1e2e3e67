// The bridge from a device profile to the emulator: the one place that turns a profile's
// emulator figures (SimParameters) into a sim::GpuConfig. Its own library so the cost
// model itself stays free of the emulator (it needs only sim/counters.h).
#pragma once

#include "gpu_model/device_profile.h"
#include "sim/render_pass.h"

namespace skinsim::gpu_model {

// The emulator configuration a profile describes (tile size, cores, texture cache), with
// `threads` host threads. Throws ProfileError, naming the file and fields, if the profile's
// tiles are not square (the emulator's are).
sim::GpuConfig gpu_config(const DeviceProfile& profile, int threads);

}  // namespace skinsim::gpu_model
