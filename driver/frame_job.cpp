#include "driver/frame_job.h"

#include "driver/skin_diagnosis.h"
#include "gpu_model/frame_cost.h"
#include "gpu_model/gpu_config.h"
#include "pipeline/reference/reference.h"
#include "sim/pass_memo.h"
#include "util/check.h"

namespace skinsim::driver {

pipeline::PipelineConfig resolve_config(pipeline::PipelineConfig config,
                                        const gpu_model::DeviceProfile& device) {
  std::tie(config.width, config.height) =
      pipeline::render_size(config, static_cast<int>(device.display_width.value),
                            static_cast<int>(device.display_height.value));
  config.validate();
  return config;
}

FrameResult run_frame(const pipeline::GpuScene& scene, const pipeline::PipelineConfig& config,
                      const gpu_model::DeviceProfile& device, int threads,
                      const PassCapture& capture, sim::PassMemo* memo) {
  SKINSIM_CHECK(config.width > 0 && config.height > 0);  // resolve_config first
  sim::Gpu gpu(gpu_model::gpu_config(device, threads));
  if (capture) gpu.set_pass_capture(capture);
  gpu.set_pass_memo(memo);
  FrameResult r;
  r.config = config;
  r.output = pipeline::render_frame(scene, config, gpu);
  if (memo) memo->end_frame();
  r.timing = gpu_model::estimate_frame(r.output.passes, device);
  r.range = gpu_model::frame_ms_range(r.output.passes, device);
  return r;
}

FrameJobResult run_frame_job(const FrameJob& job) {
  SKINSIM_CHECK(job.device != nullptr);
  const auto warn = [&job](const std::string& message) {
    if (job.scene.warn) job.scene.warn(message);
  };
  FrameJobResult r;
  const float aspect = static_cast<float>(job.config.width) / static_cast<float>(job.config.height);
  r.scene = std::make_unique<scene::Scene>(load_scene(job.scene, aspect));
  r.gpu_scene = std::make_unique<pipeline::GpuScene>(*r.scene);
  r.frame = run_frame(*r.gpu_scene, job.config, *job.device, job.threads, job.capture);
  for (const std::string& notice : r.frame.output.notices) warn(notice);
  if (job.reference) {
    r.reference =
        reference_images(pipeline::render_reference(*r.gpu_scene, job.config, job.threads));
    r.quality = evaluate_quality(r.frame.output.frame, *r.reference);
    if (!r.quality->has_skin_metrics()) {
      r.no_skin = no_skin_reason(*r.scene, job.scene.skin_materials);
      warn(r.no_skin + " (skin metrics not available)");
    }
  }
  return r;
}

}  // namespace skinsim::driver
