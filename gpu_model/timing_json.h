// JSON views of cost-model results (for reports and sweep tables).
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "gpu_model/sensitivity.h"
#include "gpu_model/timing.h"

namespace skinsim::gpu_model {

nlohmann::json to_json(const DramBytes& bytes);  // by cause, plus "total"
// Per pass: name, ms, exposed_ms, ta_ms, render_ms, bottleneck, utilisation and busy_ms per
// unit, dram_bytes by cause, schedule. Per frame: device, frame_ms, fps, dram_bytes.
nlohmann::json to_json(const FrameTiming& frame);
// Per tile: x, y, core, start_ms, ms, bottleneck (for heat maps).
nlohmann::json tiles_to_json(const PassTiming& pass);
nlohmann::json to_json(const std::vector<SensitivityRow>& rows);

}  // namespace skinsim::gpu_model
