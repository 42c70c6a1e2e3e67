// JSON views of cost-model results (for reports and sweep tables).
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "gpu_model/energy.h"
#include "gpu_model/sensitivity.h"
#include "gpu_model/timing.h"

namespace skinsim::gpu_model {

nlohmann::json to_json(const DramBytes& bytes);  // by cause, plus "total"
// Per pass: name, ms (its share of the frame, PassSlot::exposed_ms), standalone_ms, ta_ms,
// render_ms, bottleneck, utilisation (of standalone_ms) and busy_ms per unit, dram_bytes by
// cause, schedule. Per frame: device, frame_ms, fps, pipeline_ms, bandwidth_ms, dram_wait_ms
// (the passes' ms plus dram_wait_ms add up to frame_ms), dram_bytes.
nlohmann::json to_json(const FrameTiming& frame);
nlohmann::json to_json(const EnergyParts& energy);  // mJ by cause, plus "total"
// The frame's energy (FrameTiming::energy): frame_mj with low_mj/high_mj, mj by cause,
// average_power_mw over max(frame_ms, budget_ms), and per pass mj by cause with its range.
nlohmann::json energy_to_json(const FrameTiming& frame, double budget_ms = kPowerBudgetMs);
// Per tile: x, y, core, start_ms, ms, bottleneck (for heat maps).
nlohmann::json tiles_to_json(const PassTiming& pass);
nlohmann::json to_json(const std::vector<SensitivityRow>& rows);
// A profile's identity and key figures, as `skinsim devices --json` prints them.
nlohmann::json device_json(const DeviceProfile& p);

}  // namespace skinsim::gpu_model
