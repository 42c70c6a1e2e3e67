// Primitive terms shared by the tiler and tile cost: shader issue cycles, clock, bandwidth.
#pragma once

#include "gpu_model/device_profile.h"
#include "sim/op_profile.h"

namespace skinsim::gpu_model {

// Issue cycles of one shader invocation on one USSE pipe.
double shader_cycles(const sim::OpProfile& ops, const DeviceProfile& profile);

// Core clock cycles per millisecond.
double cycles_per_ms(const DeviceProfile& profile);

// Achievable DRAM bytes per millisecond.
double dram_bytes_per_ms(const DeviceProfile& profile);

// Parameter-buffer bytes of one binned vertex.
double pb_vertex_bytes(const DeviceProfile& profile, double varying_floats);

}  // namespace skinsim::gpu_model
