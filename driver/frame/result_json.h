// result.json: what a run did (counters per pass and per draw, op profiles), what the cost
// model says it costs, and what else the run measured. Assembled here alone.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "driver/frame/frame_job.h"
#include "driver/frame/frame_quality.h"
#include "gpu_model/sensitivity.h"
#include "sim/counters.h"

namespace skinsim::driver {

nlohmann::json to_json(const sim::OpProfile& profile);
nlohmann::json to_json(const sim::PassCounters& pass);  // without the per-tile array
nlohmann::json frame_result_json(const FrameResult& result, const std::string& scene_label);
// "scene_scale": units per mm and where they came from ("--units-per-mm", "file metres",
// "head height", "bounding box"), and the head measured (scene/head_measure.h) if any.
nlohmann::json scene_scale_json(const scene::Scene& scene);

// What result.json holds beside the frame; a part the run did not make is left out. The parts
// made by libraries above this one (a sequence's summary, the truth's judgement) come as JSON.
struct RunRecord {
  std::string device;
  const scene::Scene* scene = nullptr;      // "scene_scale"
  std::optional<nlohmann::json> sequence;   // driver::sequence_json
  std::optional<nlohmann::json> reference;  // FrameJobResult::reference_marker
  const FrameQuality* quality = nullptr;    // the metrics against the reference
  std::string no_skin;                      // why the skin metrics are missing
  std::optional<std::vector<gpu_model::SensitivityRow>> sensitivity;  // --sensitivity
  std::optional<nlohmann::json> truth;  // the truth's judgement (--truth)
  std::vector<std::string> warnings;
};
nlohmann::json run_result_json(const FrameResult& result, const std::string& scene_label,
                               const RunRecord& record);
// Writes result.json atomically. Paths and names come from the user as raw bytes and JSON must
// be UTF-8, so invalid bytes are written as U+FFFD rather than throwing after the frame has
// been rendered.
void write_result_json(const nlohmann::json& json, const std::filesystem::path& path);

}  // namespace skinsim::driver
