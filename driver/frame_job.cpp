#include "driver/frame_job.h"

#include "driver/skin_diagnosis.h"
#include "pipeline/reference/reference.h"
#include "util/check.h"

namespace skinsim::driver {

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
