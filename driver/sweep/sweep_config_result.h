// One finished sweep configuration as stored in configs/<id>.json: the fingerprint it was
// computed for (resume reuses it only when that still matches), its row of the sweep table,
// the per-tile cost map of its `skin` pass and the cost model's sensitivity for it.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "driver/frame/frame_job.h"
#include "driver/frame/frame_quality.h"
#include "driver/sweep/sweep_spec.h"
#include "gpu_model/device_profile.h"
#include "results/sweep_table.h"

namespace skinsim::driver {

struct StoredConfig {
  nlohmann::json fingerprint;
  results::ConfigResult row;
  std::optional<results::TileHeatmap> heatmap;  // of the pass named kHeatmapPass, if it ran
  std::vector<results::SensitivityRow> sensitivity;
  std::vector<std::string> assumptions;  // uncertain device figures, one sentence each
  // Its images (relative to the sweep directory) and a digest of each as written
  // (xxh3_fingerprint, util/fingerprint.h), so a resumed sweep or a merge tells a damaged one
  // and computes it again.
  std::map<std::string, std::string> files;
};

// The pass whose per-tile cost the report maps (the final skin shading, the costliest).
inline constexpr const char* kHeatmapPass = "skin";

// The table row of a finished frame: every knob, frame and per-pass cost with DRAM bytes by
// cause, the quality metrics and whether it differs visibly from the reference; image paths
// relative to the sweep directory. The comparisons with other rows come later
// (sweep_comparisons.h).
results::ConfigResult config_row(const SweepConfig& config, const FrameResult& frame,
                                 const FrameQuality& quality, const std::string& frame_image,
                                 const std::string& error_image,
                                 const std::string& reference_image);

// Per-tile ms and bottleneck of the pass named `pass` (nullopt if the frame has none).
std::optional<results::TileHeatmap> pass_heatmap(const FrameResult& frame, const std::string& pass,
                                                 const std::string& config_id);

// How the frame time moves over each uncertain device figure's range (cost model only: the
// figures that change the emulator's counters are left out, see assumptions), and one
// assumption sentence per uncertain figure.
void add_sensitivity(const FrameResult& frame, const gpu_model::DeviceProfile& device,
                     StoredConfig& stored);

nlohmann::json to_json(const StoredConfig& stored);
// Reads configs/<id>.json; nullopt if it is missing or not a complete stored configuration
// (e.g. written by another version): the configuration is then computed again.
std::optional<StoredConfig> read_stored_config(const std::filesystem::path& path);

}  // namespace skinsim::driver
