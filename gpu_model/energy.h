// Dynamic energy of a frame from the emulator's counters: DRAM bytes, ALU lane operations by
// precision, texture operations and depth tests, each times the profile's [energy] figure.
// Static (leakage) power and the display are left out. Every term is linear in its figure,
// so the frame's range is the sum at all figures' minima and at all their maxima.
#pragma once

#include <vector>

#include "gpu_model/device_profile.h"
#include "gpu_model/timing.h"
#include "sim/counters.h"

namespace skinsim::gpu_model {

// `timing` holds the cost model's estimate of the same passes (their DRAM bytes, after
// framebuffer compression, are the ones priced).
FrameEnergy estimate_energy(const std::vector<sim::PassCounters>& passes,
                            const std::vector<PassTiming>& timing, const DeviceProfile& profile);

// The frame budget `skinsim run` reports power at: 30 fps, the sweep's default budget
// (driver/sweep/sweep_spec.h).
inline constexpr double kPowerBudgetMs = 1000.0 / 30.0;

// Average power (mW) of a frame's energy spread over the frame budget, or over the frame
// itself when it takes longer: the GPU idles (statically, not counted) for the rest.
double average_power_mw(double energy_mj, double frame_ms, double budget_ms);

}  // namespace skinsim::gpu_model
