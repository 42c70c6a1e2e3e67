#include "driver/frame_job.h"

#include <filesystem>

#include "driver/images.h"
#include "driver/reference_cache.h"
#include "driver/skin_diagnosis.h"
#include "io/read_file.h"
#include "pipeline/reference/reference.h"
#include "util/check.h"

namespace skinsim::driver {

namespace {

// result.json's "reference" of a previous run in `dir`; null when there is none or it is not
// JSON (a damaged or foreign directory is not an error here: the reference is rendered).
nlohmann::json previous_marker(const std::filesystem::path& dir) {
  const std::filesystem::path result = dir / "result.json";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(result, ec)) return nullptr;
  try {
    const nlohmann::json j = nlohmann::json::parse(
        io::read_regular_file(result, "previous run's result"), nullptr, false);
    return j.is_object() && j.contains("reference") ? j["reference"] : nlohmann::json(nullptr);
  } catch (const std::exception&) {
    return nullptr;
  }
}

}  // namespace

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
    r.reference_marker = reference_marker(job.config, scene_fingerprint(job.scene));
    ReferenceImages kept;
    if (!job.previous_run.empty() && previous_marker(job.previous_run) == r.reference_marker &&
        load_reference(job.previous_run / kRunReferenceImage,
                       job.previous_run / reference_mask_path(kRunReferenceImage), kept)) {
      r.reference = std::move(kept);
      r.reference_source = ReferenceSource::kKept;
    } else if (job.reference_store) {
      r.reference = job.reference_store->load(r.reference_marker);
      if (r.reference) r.reference_source = ReferenceSource::kStore;
    }
    if (!r.reference) {
      r.reference =
          reference_images(pipeline::render_reference(*r.gpu_scene, job.config, job.threads));
      r.reference_source = ReferenceSource::kRendered;
      if (job.reference_store) {
        r.reference_not_stored = job.reference_store->keep(r.reference_marker, *r.reference);
      }
    }
    r.quality = evaluate_quality(to_image(r.frame.output.frame), *r.reference);
    if (!r.quality->has_skin_metrics()) {
      r.no_skin = no_skin_reason(*r.scene, job.scene.skin_materials);
      warn(r.no_skin + " (skin metrics not available)");
    }
  }
  return r;
}

}  // namespace skinsim::driver
