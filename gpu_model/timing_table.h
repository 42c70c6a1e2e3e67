// Human-readable tables (fixed-width text) of cost-model results and device profiles.
#pragma once

#include <string>
#include <vector>

#include "gpu_model/device_profile.h"
#include "gpu_model/sensitivity.h"
#include "gpu_model/timing.h"

namespace skinsim::gpu_model {

// One row per pass (its ms = share of the frame, bottleneck, TA, 3D and standalone ms,
// utilisation, core balance, DRAM MB), a dram_wait row when the frame is bandwidth-bound, and
// the frame; the rows' ms add up to the frame's.
std::string format_frame_table(const FrameTiming& frame);
// What each column of format_frame_table means, a few lines to print under it.
std::string frame_table_legend();

std::string format_sensitivity_table(const std::vector<SensitivityRow>& rows);

// Key figures of the given profiles, one row each.
std::string format_device_table(const std::vector<DeviceProfile>& profiles);

}  // namespace skinsim::gpu_model
