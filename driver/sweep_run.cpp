#include "driver/sweep_run.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>

#include "driver/frame_job.h"
#include "driver/images.h"
#include "driver/sweep_config_result.h"
#include "driver/sweep_progress.h"
#include "driver/sweep_reference.h"
#include "gpu_model/profile_loader.h"
#include "pipeline/skin_pipeline.h"
#include "quality/image.h"
#include "reports/atomic_file.h"

namespace skinsim::driver {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A scene depends on the aspect ratio of the frame (camera framing), so each resolution gets
// its own; GpuScene keeps a reference to its Scene.
struct SceneForSize {
  std::unique_ptr<scene::Scene> scene;
  std::unique_ptr<pipeline::GpuScene> gpu;
};

// A configuration to compute, with everything resolved.
struct Job {
  const SweepConfig* config = nullptr;
  const gpu_model::DeviceProfile* device = nullptr;
  pipeline::PipelineConfig resolved;  // resolution filled in
  nlohmann::json fingerprint;
  const pipeline::GpuScene* scene = nullptr;
  const ReferenceImages* reference = nullptr;
};

bool cancelled(const SweepRunOptions& o) {
  return o.cancel && o.cancel->load();
}

bool finished_before(const fs::path& dir, const Job& job) {
  const std::optional<StoredConfig> stored =
      read_stored_config(dir / config_json_path(job.config->id));
  return stored && stored->fingerprint == job.fingerprint &&
         fs::exists(dir / config_frame_path(job.config->id)) &&
         fs::exists(dir / config_error_path(job.config->id));
}

// Renders, times and measures one configuration and writes its files; the JSON goes last, so
// a configuration counts as finished only once all its files are in place.
void compute(const fs::path& dir, const Job& job) {
  const std::string& id = job.config->id;
  // One host thread per frame: the configurations themselves run in parallel, and the
  // emulator's results do not depend on its thread count.
  const FrameResult frame = run_frame(*job.scene, job.resolved, *job.device, 1);
  const FrameQuality measured = evaluate_quality(frame.output.frame, *job.reference);
  write_png(frame.output.frame, dir / config_frame_path(id));
  quality::save_png(measured.error_map, dir / config_error_path(id));
  StoredConfig stored;
  stored.fingerprint = job.fingerprint;
  stored.row =
      config_row(*job.config, frame, measured, config_frame_path(id), config_error_path(id));
  stored.heatmap = pass_heatmap(frame, kHeatmapPass, id);
  add_sensitivity(frame, *job.device, stored);
  reports::write_file_atomically((dir / config_json_path(id)).string(),
                                 to_json(stored).dump(1) + "\n");
}

}  // namespace

std::string config_json_path(const std::string& id) {
  return "configs/" + id + ".json";
}
std::string config_frame_path(const std::string& id) {
  return "configs/" + id + "_frame.png";
}
std::string config_error_path(const std::string& id) {
  return "configs/" + id + "_flip.png";
}

SweepRunSummary run_sweep(const SweepSpec& spec, const std::vector<SweepConfig>& configs,
                          const SweepRunOptions& options) {
  const Clock::time_point start = Clock::now();
  const fs::path dir(options.out_dir);

  // Devices first: an unknown profile fails before any work or directory.
  std::map<std::string, gpu_model::DeviceProfile> devices;
  for (const SweepConfig& c : configs) {
    if (!devices.count(c.device)) {
      devices.emplace(c.device, gpu_model::load_device_profile(c.device, options.data_dir));
    }
  }
  fs::create_directories(dir / "configs");

  SweepRunSummary summary;
  summary.total = static_cast<int>(configs.size());
  std::vector<Job> jobs;
  for (const SweepConfig& c : configs) {
    Job job;
    job.config = &c;
    job.device = &devices.at(c.device);
    job.resolved = c.config;
    std::tie(job.resolved.width, job.resolved.height) =
        pipeline::render_size(c.config, static_cast<int>(job.device->display_width.value),
                              static_cast<int>(job.device->display_height.value));
    job.resolved.validate();
    job.fingerprint = config_fingerprint(c, spec.scene, job.resolved.width, job.resolved.height);
    if (finished_before(dir, job)) {
      ++summary.resumed;
    } else {
      jobs.push_back(std::move(job));
    }
  }

  SweepProgress progress(summary.total, summary.resumed, options.progress);
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);

  // Scenes and references for the configurations still to do, each built once.
  std::map<std::string, SceneForSize> scenes;         // by "WxH"
  std::map<std::string, ReferenceImages> references;  // by reference_stem
  for (Job& job : jobs) {
    if (cancelled(options)) break;
    const int w = job.resolved.width, h = job.resolved.height;
    SceneForSize& s = scenes[std::to_string(w) + "x" + std::to_string(h)];
    if (!s.gpu) {
      s.scene = std::make_unique<scene::Scene>(
          load_scene(spec.scene, static_cast<float>(w) / static_cast<float>(h)));
      s.gpu = std::make_unique<pipeline::GpuScene>(*s.scene);
    }
    job.scene = s.gpu.get();
    const std::string stem = reference_stem(job.resolved, spec.scene);
    auto it = references.find(stem);
    if (it == references.end()) {
      bool rendered = false;
      ReferenceImages images;
      arena.execute([&] {
        images = cached_reference(*s.gpu, job.resolved, spec.scene, dir / "refs", options.threads,
                                  &rendered);
      });
      summary.references_rendered += rendered ? 1 : 0;
      it = references.emplace(stem, std::move(images)).first;
    }
    job.reference = &it->second;
  }

  std::mutex mutex;
  std::atomic<int> not_run{0};
  progress.start_configs();
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, jobs.size(), 1),
        [&](const tbb::blocked_range<std::size_t>& range) {
          for (std::size_t i = range.begin(); i != range.end(); ++i) {
            if (cancelled(options) || !jobs[i].reference) {
              ++not_run;
              continue;
            }
            const Clock::time_point t0 = Clock::now();
            compute(dir, jobs[i]);
            progress.finished(jobs[i].config->id, seconds_since(t0));
            const std::lock_guard lock(mutex);
            summary.computed.push_back(jobs[i].config->id);
            if (options.on_finished) options.on_finished(jobs[i].config->id);
          }
        },
        tbb::simple_partitioner());
  });
  progress.close();
  summary.not_run = not_run.load();
  summary.cancelled = cancelled(options);
  summary.seconds = seconds_since(start);
  return summary;
}

}  // namespace skinsim::driver
