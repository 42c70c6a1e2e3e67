#include "driver/frame/frame_job.h"

#include <filesystem>

#include "driver/frame/frame_work.h"
#include "driver/frame/images.h"
#include "driver/frame/reference_cache.h"
#include "driver/frame/skin_diagnosis.h"
#include "io/json_input.h"
#include "pipeline/reference/reference.h"
#include "util/check.h"

namespace skinsim::driver {

namespace {

// result.json's "reference" of a previous run in `dir` (its kept marker); null when there is
// none or it is not JSON (a damaged or foreign directory is not an error here: the reference
// is rendered).
nlohmann::json previous_marker(const std::filesystem::path& dir) {
  const std::filesystem::path result = dir / "result.json";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(std::filesystem::symlink_status(result, ec))) {
    return nullptr;
  }
  try {
    const nlohmann::json j = io::read_json_file(result, "previous run's result");
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
  const FrameWork work = estimate_frame_work(*r.gpu_scene, job.config);
  require_bounded_work(work, job.config, job.scene.label());
  for (const std::string& note : frame_work_notes(work, job.config)) warn(note);
  r.frame = run_frame(*r.gpu_scene, job.config, *job.device, job.threads, job.capture);
  for (const std::string& notice : r.frame.output.notices) warn(notice);
  if (job.reference) {
    const nlohmann::json marker = reference_marker(job.config, scene_fingerprint(job.scene));
    const auto note = [&r](const std::string& where, const KeptReference& kept) {
      if (!kept.discarded.empty()) {
        r.reference_discarded.push_back("discarded the reference kept in " + where + ": " +
                                        kept.discarded);
      }
    };
    if (!job.previous_run.empty()) {
      const nlohmann::json previous = previous_marker(job.previous_run);
      KeptReference kept;
      if (!previous.is_null()) {
        kept = load_kept_reference(previous, marker, job.config.width, job.config.height,
                                   job.previous_run / kRunReferenceImage,
                                   job.previous_run / reference_mask_path(kRunReferenceImage));
      }
      note(job.previous_run.string(), kept);
      r.reference = std::move(kept.images);
      if (r.reference) r.reference_source = ReferenceSource::kKept;
    }
    if (!r.reference && job.reference_store) {
      KeptReference kept = job.reference_store->load(marker, job.config.width, job.config.height);
      note("the reference store " + job.reference_store->dir().string(), kept);
      r.reference = std::move(kept.images);
      if (r.reference) r.reference_source = ReferenceSource::kStore;
    }
    if (!r.reference) {
      r.reference =
          reference_images(pipeline::render_reference(*r.gpu_scene, job.config, job.threads));
      r.reference_source = ReferenceSource::kRendered;
      if (job.reference_store) {
        r.reference_not_stored = job.reference_store->keep(marker, *r.reference);
      }
    }
    r.reference_marker = kept_reference_marker(marker, *r.reference);
    r.quality = evaluate_quality(to_image(r.frame.output.frame), *r.reference);
    if (!r.quality->has_skin_metrics()) {
      r.no_skin = no_skin_reason(*r.scene, job.scene.skin_materials);
      warn(r.no_skin + " (skin metrics not available)");
    }
  }
  return r;
}

}  // namespace skinsim::driver
