// Human-readable tables (fixed-width text) of cost-model results and device profiles.
#pragma once

#include <string>
#include <vector>

#include "gpu_model/device_profile.h"
#include "gpu_model/sensitivity.h"
#include "gpu_model/timing.h"

namespace skinsim::gpu_model {

// One row per pass (TA, 3D and exposed ms, bottleneck, utilisation, DRAM MB) and a total.
std::string format_frame_table(const FrameTiming& frame);

std::string format_sensitivity_table(const std::vector<SensitivityRow>& rows);

// Key figures of the given profiles, one row each.
std::string format_device_table(const std::vector<DeviceProfile>& profiles);

}  // namespace skinsim::gpu_model
