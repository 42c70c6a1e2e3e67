// Primitive terms shared by the tiler and tile cost: shader issue cycles, clock, bandwidth.
#pragma once

#include "gpu_model/device_profile.h"
#include "shading/op_profile.h"
#include "sim/counters.h"

namespace skinsim::gpu_model {

// Issue cycles of one shader invocation on one USSE pipe.
double shader_cycles(const sim::OpProfile& ops, const DeviceProfile& profile);

// Fragments a GPU of the profile's class shades for one draw in one tile: the visible ones
// (deferred HSR) plus the order-dependent overdraw it does not remove (hsr.overdraw_removed).
double fragments_shaded_on(const sim::DrawFragments& fragments, const DeviceProfile& profile);

// Bilinear TMU operations of the samples counted: trilinear and wide-format samples cost
// more than one.
double texture_ops(const sim::TextureCounters& texture, const DeviceProfile& profile);

// Render-target DRAM bytes after the profile's framebuffer compression.
double compressed_target_bytes(std::uint64_t bytes, const DeviceProfile& profile);

// Core clock cycles per millisecond.
double cycles_per_ms(const DeviceProfile& profile);

// Achievable DRAM bytes per millisecond.
double dram_bytes_per_ms(const DeviceProfile& profile);

// Parameter-buffer bytes of one binned vertex.
double pb_vertex_bytes(const DeviceProfile& profile, double varying_floats);

}  // namespace skinsim::gpu_model
