// result.json: what a run did (counters per pass and per draw, op profiles) and what the
// cost model says it costs.
#pragma once

#include <nlohmann/json.hpp>

#include "driver/frame_job.h"
#include "sim/counters.h"

namespace skinsim::driver {

nlohmann::json to_json(const sim::OpProfile& profile);
nlohmann::json to_json(const sim::PassCounters& pass);  // without the per-tile array
nlohmann::json frame_result_json(const FrameResult& result, const std::string& scene_label);
// "scene_scale": units per mm and where they came from ("--units-per-mm", "file metres",
// "head height", "bounding box"), and the head measured (scene/head_measure.h) if any.
nlohmann::json scene_scale_json(const scene::Scene& scene);

}  // namespace skinsim::driver
