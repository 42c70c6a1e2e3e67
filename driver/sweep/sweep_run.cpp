#include "driver/sweep/sweep_run.h"

#include <fmt/format.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <set>

#include "driver/frame/frame_job.h"
#include "driver/frame/images.h"
#include "driver/frame/skin_diagnosis.h"
#include "driver/sequence/sequence_animation.h"
#include "driver/sequence/sequence_sweep.h"
#include "driver/sweep/sweep_config_result.h"
#include "driver/sweep/sweep_progress.h"
#include "driver/sweep/sweep_reference.h"
#include "driver/sweep/sweep_thumbnails.h"
#include "gpu_model/device_profile.h"
#include "gpu_model/profile_loader.h"
#include "image/image.h"
#include "io/atomic_file.h"
#include "io/read_file.h"
#include "pipeline/frame.h"
#include "sim/pass_memo.h"
#include "util/build_identity.h"
#include "util/fingerprint.h"

namespace skinsim::driver {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A scene depends on the aspect ratio of the frame (camera framing), so each resolution gets
// its own; GpuScene keeps a reference to its Scene. In a sweep over a glTF animation, `scene` is
// posed at the shown frame's time and `animated` poses every frame.
struct SceneForSize {
  std::unique_ptr<scene::Scene> scene;
  std::unique_ptr<pipeline::GpuScene> gpu;
  std::unique_ptr<AnimatedScene> animated;
};

// A configuration to compute, with everything resolved.
struct Job {
  const SweepConfig* config = nullptr;
  const gpu_model::DeviceProfile* device = nullptr;
  pipeline::PipelineConfig resolved;  // resolution filled in
  nlohmann::json fingerprint;
  const pipeline::GpuScene* scene = nullptr;
  AnimatedScene* animated = nullptr;  // an animated sequence's frames
  const ReferenceImages* reference = nullptr;
  std::string reference_image;  // relative path of its cached reference PNG
};

bool cancelled(const SweepRunOptions& o) {
  return o.cancel && o.cancel->load();
}

enum class Stored { kNone, kFinished, kForeign, kDamaged };

// The first of a stored configuration's images that is missing or not the one it wrote
// (truncated, replaced), or "".
std::string damaged_image(const fs::path& dir, const Job& job, const StoredConfig& stored) {
  for (const std::string& image :
       {config_frame_path(job.config->id), config_error_path(job.config->id)}) {
    const auto digest = stored.files.find(image);
    try {
      if (digest == stored.files.end() ||
          xxh3_fingerprint({io::read_regular_file(dir / image, "image")}) != digest->second) {
        return image;
      }
    } catch (const io::InputError&) {
      return image;
    }
  }
  return "";
}

// Whether this configuration is finished in `dir`, damaged (an image missing or not the one
// written: `damaged` names it), or its id holds another sweep's result.
Stored stored_state(const fs::path& dir, const Job& job, std::string& damaged) {
  const std::optional<StoredConfig> stored =
      read_stored_config(dir / config_json_path(job.config->id));
  if (!stored) return Stored::kNone;
  if (stored->fingerprint != job.fingerprint) return Stored::kForeign;
  damaged = damaged_image(dir, job, *stored);
  return damaged.empty() ? Stored::kFinished : Stored::kDamaged;
}

// Why a row cannot be stored, or "": a NaN or infinite figure would be written as JSON null,
// fail to read back, and so be recomputed on every resume without a word.
std::string non_finite_figure(const results::ConfigResult& row) {
  std::vector<std::pair<std::string, double>> figures = {
      {"frame_ms", row.frame_ms}, {"fps", row.fps}, {"dram_bytes", row.dram_bytes}};
  for (const auto& [name, value] : row.quality) figures.emplace_back("quality." + name, value);
  for (const auto& [name, value] : figures) {
    if (!std::isfinite(value)) return fmt::format("{} is {} (not a finite number)", name, value);
  }
  return "";
}

// Measures a rendered configuration and writes its files; the JSON goes last, so a
// configuration counts as finished only once all its files are in place. Throws SweepError when
// a figure is not a finite number.
void finish(const fs::path& dir, const Job& job, const FrameResult& frame, image::Image image,
            const std::optional<results::SequenceSummary>& sequence) {
  const std::string& id = job.config->id;
  FrameQuality measured = evaluate_quality(image, *job.reference);
  // Each PNG's deflate stream is encoded by one thread: the two at once, each with its
  // thumbnail for the report while its pixels are at hand.
  // Each returns its file's digest, of the bytes it wrote (no reading back).
  std::string frame_digest, error_digest;
  tbb::parallel_invoke(
      [&] {
        frame_digest = write_image_and_thumbnail(std::move(image), dir, config_frame_path(id));
      },
      [&] {
        error_digest =
            write_image_and_thumbnail(std::move(measured.error_map), dir, config_error_path(id));
      });
  StoredConfig stored;
  stored.files = {{config_frame_path(id), frame_digest}, {config_error_path(id), error_digest}};
  stored.fingerprint = job.fingerprint;
  // config_row reads the metrics; the error map went into its PNG above.
  stored.row = config_row(*job.config, frame, measured, config_frame_path(id),
                          config_error_path(id), job.reference_image);
  if (sequence) results::apply_sequence_summary(stored.row, *sequence);
  if (const std::string bad = non_finite_figure(stored.row); !bad.empty()) throw SweepError(bad);
  stored.heatmap = pass_heatmap(frame, kHeatmapPass, id);
  add_sensitivity(frame, *job.device, stored);
  io::write_file_atomically((dir / config_json_path(id)).string(), to_json(stored).dump(1) + "\n");
}

// A configuration whose frame is rendered and whose measuring and files (finish) run while the
// next configuration's frame renders.
struct Finishing {
  const Job* job = nullptr;
  Clock::time_point start;  // of its frame
  Clock::time_point done;   // of its files
  FrameResult frame;        // its counters and timing; its render targets are let go
  image::Image image;       // its frame, converted
  std::optional<results::SequenceSummary> sequence;  // of a sweep over a sequence
  std::string failure;  // why it could not be measured, if it could not
};

// What a configuration is expected to cost the host, for balancing shards: its output pixels
// times its technique's measured host time per pixel (TechniqueSpec::host_ns_per_pixel).
std::uint64_t expected_host_cost(const pipeline::PipelineConfig& resolved) {
  return static_cast<std::uint64_t>(resolved.width) * static_cast<std::uint64_t>(resolved.height) *
         pipeline::find_technique(resolved.technique).host_ns_per_pixel;
}

// A sequence's per-frame references, kept in refs/ like the sweep's own, keyed by the frame's
// pose too in an animated sequence.
SequenceReferences sweep_references(const nlohmann::json& scene_fp, const fs::path& dir,
                                    const SweepRunOptions& o) {
  return [&scene_fp, dir, &o](const pipeline::GpuScene& scene,
                              const pipeline::PipelineConfig& frame, double time_s) {
    return cached_reference(scene, frame, posed_scene_fingerprint(scene_fp, *o.sequence, time_s),
                            dir / "refs", o.threads,
                            o.reference_store ? &*o.reference_store : nullptr);
  };
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

namespace {

// The device profiles the configurations name, each loaded once, and their files' fingerprints.
struct Devices {
  std::map<std::string, gpu_model::DeviceProfile> profiles;
  std::map<std::string, std::string> fingerprints;
};

// Devices first: an unknown profile fails before any work or directory. A stored result made
// with other figures (an edited profile) is not this sweep's: the profile's bytes are part of
// the fingerprint.
Devices load_devices(const std::vector<SweepConfig>& configs, const std::string& data_dir) {
  Devices devices;
  for (const SweepConfig& c : configs) {
    if (devices.profiles.count(c.device)) continue;
    const gpu_model::DeviceProfile& device =
        devices.profiles.emplace(c.device, gpu_model::load_device_profile(c.device, data_dir))
            .first->second;
    devices.fingerprints[c.device] =
        content_fingerprint(io::read_regular_file(device.source_path, "device profile"));
  }
  return devices;
}

// What this run (or shard) computes: its configurations not yet finished in the directory,
// and the ids that hold another sweep's result.
struct SweepPlan {
  nlohmann::json scene_fp;  // scene_fingerprint, read once (a scan's bytes), not per job
  std::vector<Job> jobs;
  std::set<std::string> foreign;
  ShardStatus status;  // written only by a shard
};

// What each configuration is expected to cost the host (expected_host_cost), for balancing
// shards.
std::vector<std::uint64_t> expected_costs(const std::vector<SweepConfig>& configs,
                                          const Devices& devices) {
  std::vector<std::uint64_t> costs;
  for (const SweepConfig& c : configs) {
    costs.push_back(expected_host_cost(resolve_config(c.config, devices.profiles.at(c.device))));
  }
  return costs;
}

// A configuration with everything resolved and its fingerprint: a stored result from an edited
// scene file or by another build of skinsim is not this sweep's either (scene_fingerprint,
// the build identity).
Job resolved_job(const SweepConfig& c, const Devices& devices, const nlohmann::json& scene_fp,
                 const SweepRunOptions& options) {
  Job job;
  job.config = &c;
  job.device = &devices.profiles.at(c.device);
  job.resolved = resolve_config(c.config, *job.device);
  job.fingerprint = config_fingerprint(c, scene_fp, job.resolved.width, job.resolved.height);
  job.fingerprint["device_profile"] = devices.fingerprints.at(c.device);
  job.fingerprint["build"] = build_identity();  // another skinsim may compute other figures
  if (options.sequence) job.fingerprint["sequence"] = sequence_fingerprint(*options.sequence);
  return job;
}

SweepPlan plan_sweep(const SweepSpec& spec, const std::vector<SweepConfig>& configs,
                     const Devices& devices, const fs::path& dir, const SweepRunOptions& options,
                     SweepRunSummary& summary) {
  const std::vector<std::uint64_t> costs = expected_costs(configs, devices);
  const std::vector<int> shard_of = options.shard ? assign_shards(costs, options.shard->count)
                                                  : std::vector<int>(configs.size(), 0);
  const int this_shard = options.shard ? options.shard->index : 0;
  const ShardLedger ledger(options.shard ? std::vector<ShardStatus>() : read_shard_statuses(dir),
                           costs);
  SweepPlan plan;
  if (options.shard) plan.status = {*options.shard, "running", "", {}, {}};
  plan.scene_fp = scene_fingerprint(spec.scene);
  for (std::size_t index = 0; index < configs.size(); ++index) {
    const SweepConfig& c = configs[index];
    Job job = resolved_job(c, devices, plan.scene_fp, options);
    summary.fingerprints[c.id] = job.fingerprint;
    if (shard_of[index] != this_shard) continue;  // another shard's
    ++summary.this_part;
    plan.status.configurations.push_back(c.id);
    std::string damaged;
    const Stored state = stored_state(dir, job, damaged);
    if (state == Stored::kFinished) {
      ++summary.resumed;
      continue;
    }
    if (state == Stored::kForeign) plan.foreign.insert(c.id);
    if (state == Stored::kDamaged) {
      // Its result goes with it: the tables and a merge then treat it as not yet computed,
      // instead of failing on the image.
      std::error_code ignored;
      fs::remove(dir / config_json_path(c.id), ignored);
      summary.warnings.push_back(fmt::format(
          "configuration {}: {} is missing or not the image it wrote (damaged or replaced); {}",
          c.id, damaged,
          options.compute ? "computing it again" : "run its shard, or the sweep, again"));
    }
    if (!options.compute || !ledger.empty()) {
      summary.left_by_shards.push_back({c.id, ledger.why_missing(index, c.id)});
    }
    if (options.compute) plan.jobs.push_back(std::move(job));
  }
  if (options.shard && !plan.foreign.empty()) {
    // Shards share a directory: one of another sweep (another --set knob, scene, device or
    // build) would replace the results the other sweep's shards are computing there.
    throw SweepError(fmt::format(
        "--shard {}: {} holds another sweep's results under {} of this shard's configuration "
        "ids (e.g. {}): refusing to replace them from a shard; give this sweep its own --out, "
        "or run it without --shard to replace them",
        to_string(*options.shard), dir.string(), plan.foreign.size(), *plan.foreign.begin()));
  }
  return plan;
}

// Scenes and references for the configurations still to do, each built once; the jobs point
// into them.
struct SweepInputs {
  std::map<std::string, SceneForSize> scenes;         // by "WxH"
  std::map<std::string, ReferenceImages> references;  // by reference_stem
};

// The reference of `shown`, from refs/, the store or rendered, with its FLIP features.
ReferenceImages prepare_reference(const pipeline::GpuScene& scene,
                                  const pipeline::PipelineConfig& shown,
                                  const nlohmann::json& scene_fp, const fs::path& dir,
                                  const SweepRunOptions& options, tbb::task_arena& arena,
                                  SweepRunSummary& summary) {
  ReferenceSource source = ReferenceSource::kKept;
  ReferenceImages images;
  arena.execute([&] {
    images = cached_reference(scene, shown, scene_fp, dir / "refs", options.threads,
                              options.reference_store ? &*options.reference_store : nullptr,
                              &source, options.progress);
    images.flip_features = std::make_shared<const quality::FlipFeatures>(images.image);
  });
  summary.references_rendered += source == ReferenceSource::kRendered ? 1 : 0;
  summary.references_from_store += source == ReferenceSource::kStore ? 1 : 0;
  return images;
}

void prepare_jobs(std::vector<Job>& jobs, SweepInputs& inputs, const SweepSpec& spec,
                  const nlohmann::json& scene_fp, const fs::path& dir,
                  const SweepRunOptions& options, tbb::task_arena& arena,
                  SweepRunSummary& summary) {
  for (Job& job : jobs) {
    if (cancelled(options)) break;
    const int w = job.resolved.width, h = job.resolved.height;
    SceneForSize& s = inputs.scenes[std::to_string(w) + "x" + std::to_string(h)];
    // A sequence's configurations show, and are compared on, one frame (shown_frame).
    const int shown_index = options.sequence ? shown_frame(*options.sequence) : 0;
    const double shown_time_s = options.sequence ? options.sequence->time_s(shown_index) : 0.0;
    if (!s.gpu) {
      const float aspect = static_cast<float>(w) / static_cast<float>(h);
      if (options.sequence && options.sequence->animated) {
        s.animated = std::make_unique<AnimatedScene>(spec.scene, aspect, *options.sequence);
        s.scene = std::make_unique<scene::Scene>(s.animated->pose(shown_time_s));
      } else {
        s.scene = std::make_unique<scene::Scene>(load_scene(spec.scene, aspect));
      }
      s.gpu = std::make_unique<pipeline::GpuScene>(*s.scene);
    }
    job.scene = s.gpu.get();
    job.animated = s.animated.get();
    const pipeline::PipelineConfig shown =
        options.sequence
            ? sequence_frame_config(*options.sequence, shown_index, job.resolved, *s.gpu)
            : job.resolved;
    const nlohmann::json shown_scene_fp =
        options.sequence ? posed_scene_fingerprint(scene_fp, *options.sequence, shown_time_s)
                         : scene_fp;
    const std::string stem = reference_stem(shown, shown_scene_fp);
    job.reference_image = reference_image_path(stem);
    auto it = inputs.references.find(stem);
    if (it == inputs.references.end()) {
      ReferenceImages images =
          prepare_reference(*s.gpu, shown, shown_scene_fp, dir, options, arena, summary);
      if (images.skin.count() == 0) {  // still rendered and measured, over the whole frame
        summary.warnings.push_back(fmt::format(
            "{}x{}: {} (skin metrics not available; configurations are compared by FLIP over "
            "the frame)",
            w, h, no_skin_reason(*s.scene, spec.scene.skin_materials)));
      }
      it = inputs.references.emplace(stem, std::move(images)).first;
    }
    job.reference = &it->second;
  }
}

// Renders one configuration's frame (or plays its sequence) into `next`, its render targets
// let go once converted.
void render_job(const Job& job, const nlohmann::json& scene_fp, const fs::path& dir,
                const SweepRunOptions& options, tbb::task_arena& arena, sim::PassMemo& memo,
                Finishing& next, std::vector<std::string>& warnings) {
  if (options.sequence) {
    PlayedConfig played = play_sweep_config(
        *job.scene, *options.sequence, job.resolved, *job.device, arena.max_concurrency(), memo,
        sweep_references(scene_fp, dir, options), dir, job.config->id,
        job.animated ? SceneAtTime([a = job.animated](double t) -> const pipeline::GpuScene& {
          return a->at(t);
        })
                     : SceneAtTime{});
    next.frame = std::move(played.cost_frame);
    next.image = std::move(played.shown_image);
    next.sequence = std::move(played.summary);
    if (!played.video_note.empty() &&
        std::find(warnings.begin(), warnings.end(), played.video_note) == warnings.end()) {
      warnings.push_back(played.video_note);
    }
  } else {
    next.frame =
        run_frame(*job.scene, job.resolved, *job.device, arena.max_concurrency(), {}, &memo);
    next.image = to_image(next.frame.output.frame);
  }
  next.frame.output.frame = {};
  next.frame.output.intermediates.clear();
}

// One frame at a time, with every thread of the arena: a frame's tiles use any number of
// host threads (sim/tile_stage.cpp), and its quality metrics whatever threads are free. On
// a 16-core host the default sweep's frames took 4.08 s so, against 3.44 s four at a time
// with 4 threads each (bench/thread_scaling, docs/performance.md); but four in flight
// peaked at 1415 MB against 667 MB, as each holds its render targets and a memo, and
// replayed 12 passes of 80 instead of 51, as consecutive configurations, which share
// passes, went to different lanes. The memo replays passes of earlier frames:
// configurations come in expansion order, the last axis fastest, so consecutive ones share
// the passes that axis leaves be.
//
// A configuration's measuring and files (finish) run as a task beside the next
// configuration's frame, so that the frame's serial stretches (binning, the cost model, the
// memo's hashing) and those of the metrics fill each other's idle cores. One is in flight at
// a time, for memory; it is done, and counted, before the next is started, and a sweep
// cancelled meanwhile drops the frame just rendered rather than start its files.
void execute_jobs(const std::vector<Job>& jobs, const nlohmann::json& scene_fp, const fs::path& dir,
                  const SweepRunOptions& options, tbb::task_arena& arena, SweepProgress& progress,
                  SweepRunSummary& summary) {
  arena.execute([&] {
    sim::PassMemo memo(kPassMemoBytes);
    std::unique_ptr<Finishing> finishing;
    tbb::task_group finishing_task;  // destroyed (waited for) before what it finishes
    const auto complete = [&] {
      finishing_task.wait();
      if (!finishing) return;
      const std::string& id = finishing->job->config->id;
      if (!finishing->failure.empty()) {
        // One configuration that cannot be measured (a figure that is not a finite number) is
        // reported with its reason; the others still run.
        summary.failed.push_back({id, finishing->failure});
      } else {
        // Its frame and its files, not the wait for the next frame that finish() ran beside.
        progress.finished(
            id, std::chrono::duration<double>(finishing->done - finishing->start).count());
        summary.computed.push_back(id);
        if (options.on_finished) options.on_finished(id);
      }
      finishing.reset();
    };
    for (const Job& job : jobs) {
      if (cancelled(options) || !job.reference) {
        ++summary.not_run;
        continue;
      }
      auto next = std::make_unique<Finishing>();
      next->job = &job;
      next->start = Clock::now();
      try {
        render_job(job, scene_fp, dir, options, arena, memo, *next, summary.warnings);
      } catch (const UserError& e) {
        complete();
        summary.failed.push_back({job.config->id, e.what()});
        continue;
      }
      complete();
      if (cancelled(options)) {
        ++summary.not_run;
        continue;
      }
      finishing = std::move(next);
      finishing_task.run([&dir, f = finishing.get()] {
        try {
          finish(dir, *f->job, f->frame, std::move(f->image), f->sequence);
        } catch (const UserError& e) {
          f->failure = e.what();
        }
        f->done = Clock::now();
      });
    }
    complete();
    summary.passes_replayed = memo.stats().replayed;
    summary.passes_rendered = memo.stats().rendered;
  });
}

// A shard's status file says how its part ended.
void write_shard_outcome(const fs::path& dir, const SweepRunSummary& summary, ShardStatus& status) {
  for (const FailedConfig& f : summary.failed) status.failed.emplace_back(f.id, f.reason);
  status.state = summary.cancelled ? "interrupted" : summary.failed.empty() ? "finished" : "failed";
  write_shard_status(dir, status);
}

}  // namespace

SweepRunSummary run_sweep(const SweepSpec& spec, const std::vector<SweepConfig>& configs,
                          const SweepRunOptions& options) {
  const Clock::time_point start = Clock::now();
  const fs::path dir(options.out_dir);
  const Devices devices = load_devices(configs, options.data_dir);
  fs::create_directories(dir / "configs");

  SweepRunSummary summary;
  summary.total = static_cast<int>(configs.size());
  SweepPlan plan = plan_sweep(spec, configs, devices, dir, options, summary);
  if (options.shard) write_shard_status(dir, plan.status);

  SweepProgress progress(summary.this_part, summary.resumed, options.progress);
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  SweepInputs inputs;
  prepare_jobs(plan.jobs, inputs, spec, plan.scene_fp, dir, options, arena, summary);
  progress.start_configs();
  execute_jobs(plan.jobs, plan.scene_fp, dir, options, arena, progress, summary);
  progress.close();

  for (const std::string& id : summary.computed) plan.foreign.erase(id);
  summary.foreign_ignored = static_cast<int>(plan.foreign.size());
  summary.cancelled = cancelled(options);
  if (options.shard) write_shard_outcome(dir, summary, plan.status);
  summary.seconds = seconds_since(start);
  return summary;
}

}  // namespace skinsim::driver
