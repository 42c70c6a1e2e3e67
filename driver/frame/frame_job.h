// One frame, end to end, as `run` and `check` do it: the config resolved for the device and
// checked once, the scene loaded for its aspect, the technique rendered on the emulated GPU
// configured from the device profile, the cost model's timing, and optionally the reference
// and the image quality against it. A sweep shares scenes and references between its
// configurations, so it calls the steps (resolve_config, run_frame, reference_images,
// evaluate_quality) itself.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "driver/frame/frame_quality.h"
#include "driver/frame/reference_cache.h"
#include "driver/frame/reference_store.h"
#include "driver/frame/scene_source.h"
#include "gpu_model/device_profile.h"
#include "gpu_model/sensitivity.h"
#include "gpu_model/timing.h"
#include "pipeline/config.h"
#include "pipeline/frame.h"
#include "pipeline/gpu_scene.h"

namespace skinsim::sim {
class PassMemo;
}

namespace skinsim::driver {

// What a sweep or a sequence keeps of earlier frames' passes for replay (sim::PassMemo). The passes
// worth keeping are the ones later passes sample (PassMemo::end_frame): at 2048x1536 and buffer
// scale 1 a mobile frame's are about 42 MB (shadow map, irradiance, two blurs), so this holds
// those of several scales and techniques without raising a sweep's peak much.
inline constexpr std::size_t kPassMemoBytes = std::size_t{192} << 20;

struct FrameResult {
  pipeline::PipelineConfig config;  // with the resolution resolved
  pipeline::FrameOutput output;
  gpu_model::FrameTiming timing;
  // timing.frame_ms over the profile's uncertain figures (gpu_model::frame_ms_range).
  gpu_model::FrameMsRange range;
};

// The config with its resolution resolved (default: the device's display), validated: throws
// pipeline::ConfigError naming the knob.
pipeline::PipelineConfig resolve_config(pipeline::PipelineConfig config,
                                        const gpu_model::DeviceProfile& device);

// Called with every pass once the emulated GPU has run it (sim::Gpu::set_pass_capture).
using PassCapture = std::function<void(const sim::RenderPassDesc&)>;

// Renders and times a frame of a resolved config (resolve_config). With `memo`, passes
// identical to ones an earlier frame rendered are replayed from it (sim/pass_memo.h).
FrameResult run_frame(const pipeline::GpuScene& scene, const pipeline::PipelineConfig& config,
                      const gpu_model::DeviceProfile& device, int threads,
                      const PassCapture& capture = {}, sim::PassMemo* memo = nullptr);

struct FrameJob {
  const gpu_model::DeviceProfile* device = nullptr;
  pipeline::PipelineConfig config;  // resolved (resolve_config)
  SceneSource scene;                // its `warn` receives the scene's and the frame's warnings
  int threads = 0;
  bool reference = true;  // render the reference and measure the quality against it
  PassCapture capture;    // optional: sees every pass of the frame (`skinsim export`)
  // Optional: a previous `skinsim run` directory whose reference is reused when its marker
  // (result.json's "reference": reference_marker) is this frame's, instead of rendering it.
  std::filesystem::path previous_run;
  // Optional: where references are shared with other runs and sweeps (reference_store.h): a
  // reference not found in previous_run is taken from it, and a rendered one kept in it.
  std::optional<ReferenceStore> reference_store;
};

// A run's reference image, as run_frame_job reuses it from FrameJob::previous_run (its skin
// mask beside it: reference_mask_path).
inline constexpr const char* kRunReferenceImage = "reference.png";

struct FrameJobResult {
  std::unique_ptr<scene::Scene> scene;
  std::unique_ptr<pipeline::GpuScene> gpu_scene;  // refers to *scene
  FrameResult frame;
  std::optional<ReferenceImages> reference;  // with FrameJob::reference
  nlohmann::json reference_marker;           // with FrameJob::reference: kept_reference_marker
  // Kept copies found damaged, replaced or planted, and so rendered or taken from elsewhere.
  std::vector<std::string> reference_discarded;
  ReferenceSource reference_source = ReferenceSource::kRendered;  // with FrameJob::reference
  std::string reference_not_stored;     // why a rendered reference could not be kept in the store
  std::optional<FrameQuality> quality;  // with FrameJob::reference
  // Set when the reference shows no skin (so there are no skin metrics): which rule found
  // none and what to pass (skin_diagnosis.h); also sent to `warn`.
  std::string no_skin;
};

FrameJobResult run_frame_job(const FrameJob& job);

}  // namespace skinsim::driver
