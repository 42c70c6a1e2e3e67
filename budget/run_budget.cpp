#include "budget/run_budget.h"

#include <fmt/format.h>

#include "budget/device_fingerprint.h"
#include "budget/error.h"
#include "driver/frame_job.h"
#include "driver/frame_quality.h"
#include "gpu_model/error.h"
#include "gpu_model/profile_loader.h"
#include "scene/error.h"

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
  driver::FrameJob job;
  job.device = &device;
  try {
    job.config = driver::resolve_config(budget.config, device);
  } catch (const pipeline::ConfigError& e) {
    throw BudgetError(fmt::format("{}: {}", where, e.what()));
  }
  job.scene = budget.scene;
  job.threads = threads;
  job.reference = with_quality;
  driver::FrameJobResult frame;
  try {
    frame = driver::run_frame_job(job);
  } catch (const scene::SceneError& e) {
    throw BudgetError(fmt::format("{}, scene: {}", where, e.what()));
  }
  BudgetRun run;
  run.measurement = measure_frame(frame.frame);
  if (frame.quality) {
    if (!frame.no_skin.empty()) {
      for (const Limit& limit : budget.limits) {
        if (limit.metric.ends_with("_skin")) {
          throw BudgetError(fmt::format("{}, limit '{}': {}", where, limit.metric, frame.no_skin));
        }
      }
    }
    add_quality_metrics(run.measurement, frame.quality->metrics);
  }
  run.device = device.name;
  run.device_hash = file_fingerprint(device.source_path);
  return run;
}

}  // namespace skinsim::budget
