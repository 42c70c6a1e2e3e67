#include "budget/run_budget.h"

#include <fmt/format.h>

#include "budget/device_fingerprint.h"
#include "budget/error.h"
#include "driver/frame/frame_job.h"
#include "driver/frame/frame_quality.h"
#include "driver/sequence/sequence_run.h"
#include "gpu_model/error.h"
#include "gpu_model/profile_loader.h"
#include "scene/error.h"

namespace skinsim::budget {

namespace {

// Every frame of the sequence: the worst frame's metrics, and the frame-time distribution.
Measurement measure_sequence(const driver::Sequence& sequence, const driver::FrameJob& job,
                             const std::string& where) {
  const float aspect = static_cast<float>(job.config.width) / static_cast<float>(job.config.height);
  std::unique_ptr<scene::Scene> scene;
  try {
    scene = std::make_unique<scene::Scene>(driver::load_scene(job.scene, aspect));
  } catch (const scene::SceneError& e) {
    throw BudgetError(fmt::format("{}, scene: {}", where, e.what()));
  }
  const pipeline::GpuScene gpu_scene(*scene);
  driver::SequenceResult played;
  try {
    played = driver::run_sequence(gpu_scene, sequence, job.config, *job.device, job.threads);
  } catch (const UserError& e) {  // a track's value out of its knob's range
    throw BudgetError(fmt::format("{}, sequence: {}", where, e.what()));
  }
  Measurement m = measure_frame(played.worst);
  const driver::FrameMsStats& s = played.stats;
  for (const auto& [stat, value] :
       {std::pair{"p50", s.p50}, std::pair{"p95", s.p95}, std::pair{"p99", s.p99},
        std::pair{"max", s.max}, std::pair{"mean", s.mean}}) {
    m.metrics[std::string("frame_ms.") + stat] = value;
  }
  m.sequence_summary = fmt::format(
      "over {}'s {} frames at {:g} fps: p50 {:.3f} ms, p95 {:.3f} ms, worst {:.3f} ms at frame {} "
      "({:.3f} s)",
      sequence.name, sequence.frames, sequence.fps, s.p50, s.p95, s.max, s.worst_frame,
      sequence.time_s(s.worst_frame));
  return m;
}

}  // namespace

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
  BudgetRun run;
  if (budget.sequence) {
    run.measurement = measure_sequence(*budget.sequence, job, where);
    run.device = device.name;
    run.device_hash = file_fingerprint(device.source_path);
    return run;
  }
  driver::FrameJobResult frame;
  try {
    frame = driver::run_frame_job(job);
  } catch (const scene::SceneError& e) {
    throw BudgetError(fmt::format("{}, scene: {}", where, e.what()));
  }
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
