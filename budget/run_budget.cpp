#include "budget/run_budget.h"

#include <fmt/format.h>

#include "budget/budget_error.h"
#include "budget/device_fingerprint.h"
#include "driver/frame_job.h"
#include "driver/frame_quality.h"
#include "driver/skin_diagnosis.h"
#include "gpu_model/errors.h"
#include "gpu_model/profile_loader.h"
#include "pipeline/gpu_scene.h"
#include "pipeline/reference/reference.h"
#include "scene/scene_error.h"

namespace skinsim::budget {

gpu_model::DeviceProfile load_budget_device(const std::string& file, const Budget& budget,
                                            const std::string& data_dir) {
  try {
    return gpu_model::load_device_profile(budget.device, data_dir);
  } catch (const gpu_model::ProfileError& e) {
    throw BudgetError(fmt::format("{}:{}: budget '{}', device '{}': {}", file, budget.line,
                                  budget.name, budget.device, e.what()));
  }
}

BudgetRun run_budget(const std::string& file, const Budget& budget, const std::string& data_dir,
                     int threads, bool with_quality) {
  const gpu_model::DeviceProfile device = load_budget_device(file, budget, data_dir);
  const std::string where = fmt::format("{}:{}: budget '{}'", file, budget.line, budget.name);
  pipeline::PipelineConfig config = budget.config;
  std::tie(config.width, config.height) =
      pipeline::render_size(config, static_cast<int>(device.display_width.value),
                            static_cast<int>(device.display_height.value));
  try {
    config.validate();
  } catch (const pipeline::ConfigError& e) {
    throw BudgetError(fmt::format("{}: {}", where, e.what()));
  }
  scene::Scene scene;
  try {
    scene = driver::load_scene(
        budget.scene, static_cast<float>(config.width) / static_cast<float>(config.height));
  } catch (const scene::SceneError& e) {
    throw BudgetError(fmt::format("{}, scene: {}", where, e.what()));
  }
  const pipeline::GpuScene gpu_scene(scene);
  const driver::FrameResult frame = driver::run_frame(gpu_scene, config, device, threads);
  BudgetRun run;
  run.measurement = measure_frame(frame);
  if (with_quality) {
    const driver::ReferenceImages reference =
        driver::reference_images(pipeline::render_reference(gpu_scene, frame.config, threads));
    const driver::FrameQuality quality = driver::evaluate_quality(frame.output.frame, reference);
    if (!quality.has_skin_metrics()) {
      for (const Limit& limit : budget.limits) {
        if (limit.metric.ends_with("_skin")) {
          throw BudgetError(
              fmt::format("{}, limit '{}': {}", where, limit.metric,
                          driver::no_skin_reason(scene, budget.scene.skin_materials)));
        }
      }
    }
    add_quality_metrics(run.measurement, quality.metrics);
  }
  run.device = device.name;
  run.device_hash = file_fingerprint(device.source_path);
  return run;
}

}  // namespace skinsim::budget
