// `skinsim run`: one frame of the skin pipeline on the emulated GPU, its images, counters
// and modelled timing.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <thread>

#include "app/cli_options.h"
#include "app/commands.h"
#include "driver/frame/frame_job.h"
#include "driver/frame/frame_passes.h"
#include "driver/frame/frame_quality.h"
#include "driver/frame/images.h"
#include "driver/frame/reference_cache.h"
#include "driver/frame/result_json.h"
#include "driver/sequence/sequence_animation.h"
#include "driver/sequence/sequence_charts.h"
#include "driver/sequence/sequence_page.h"
#include "driver/sequence/sequence_run.h"
#include "driver/truth/truth_judge.h"
#include "gpu_model/sensitivity.h"
#include "gpu_model/timing_json.h"
#include "gpu_model/timing_table.h"
#include "io/atomic_file.h"
#include "io/run_directory.h"
#include "pipeline/brdf_lut_texture.h"
#include "pipeline/technique.h"
#include "reports/timeline_svg.h"

namespace skinsim::app {

namespace {

constexpr const char* kFramesDir = "frames";  // a sequence's frame images, 0000.png on

struct RunOptions {
  DeviceOptions device;
  driver::SceneSource scene;
  pipeline::PipelineConfig config;
  std::string out = "out";
  bool sensitivity = false;
  bool reference = true;
  std::string truth;                 // --truth: "cached", a file, or none
  driver::TruthChoice truth_choice;  // --truth-samples, --truth-seed
  std::string sequence;              // --sequence: a preset or a sequence file; empty: one frame
  int frames = 0;                    // --frames, --fps: 0 = the sequence's own
  double fps = 0.0;
  bool charts = true;  // a sequence's charts (--no-charts)
};

// `--truth`: the frame and the reference judged by the path-traced truth beside the
// reference's figures (driver/truth/truth_judge.h), for result.json's "truth".
nlohmann::json judge_with_truth(const driver::Truth& truth, const driver::FrameJobResult& r) {
  const image::Mask* skin = r.reference ? &r.reference->skin : nullptr;
  nlohmann::json out = truth.about;
  out["noise_floor"] = driver::truth_noise_floor(truth, skin);
  out["frame"] = driver::judge_against_truth(driver::to_image(r.frame.output.frame), truth, skin);
  fmt::print("truth: {}\n", driver::truth_source_text(truth));
  fmt::print("truth's noise floor: {}\n", driver::truth_figures(out["noise_floor"]));
  fmt::print("quality vs truth: frame {}\n", driver::truth_figures(out["frame"]));
  if (r.reference) {
    out["reference"] = driver::judge_against_truth(r.reference->image, truth, skin);
    fmt::print("quality vs truth: reference {}\n", driver::truth_figures(out["reference"]));
  }
  return out;
}

// A sequence's frames: each frame's image under frames/, the per-frame results and their
// distribution for result.json's "sequence", and the emulation rate on stdout.
struct SequenceRun {
  std::unique_ptr<scene::Scene> scene;
  std::unique_ptr<pipeline::GpuScene> gpu_scene;  // refers to *scene
  driver::Sequence sequence;
  driver::SequenceResult result;
  driver::SequenceChartsOutcome charts;
  driver::SequencePage page;  // sequence.html and its video
};

SequenceRun play_sequence(const RunOptions& o, const driver::SceneSource& scene,
                          const pipeline::PipelineConfig& config,
                          const gpu_model::DeviceProfile& device, const std::filesystem::path& out,
                          std::vector<std::string>& warnings) {
  SequenceRun r;
  r.sequence = driver::load_sequence(o.sequence, o.frames, o.fps);
  driver::check_sequence(r.sequence, config);
  const float aspect = static_cast<float>(config.width) / static_cast<float>(config.height);
  driver::attach_animation(r.sequence, scene);
  std::optional<driver::AnimatedScene> animated;
  if (r.sequence.animated) animated.emplace(scene, aspect, r.sequence);
  // An animated file's first frame stands for it in the single-frame outputs (its scale).
  r.scene = std::make_unique<scene::Scene>(animated ? animated->pose(r.sequence.time_s(0))
                                                    : driver::load_scene(scene, aspect));
  r.gpu_scene = std::make_unique<pipeline::GpuScene>(*r.scene);
  std::filesystem::create_directories(out / kFramesDir);
  const auto start = std::chrono::steady_clock::now();
  r.result = driver::run_sequence(
      *r.gpu_scene, r.sequence, config, device, o.device.threads,
      [&out](int index, const driver::FrameResult& frame) {
        driver::write_png(frame.output.frame, out / kFramesDir / fmt::format("{:04d}.png", index));
      },
      o.reference ? driver::rendered_references(o.device.threads) : driver::SequenceReferences{},
      nullptr,
      animated ? [&animated](double t) -> const pipeline::GpuScene& { return animated->at(t); }
               : driver::SceneAtTime{});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const driver::SequenceResult::Notice& notice : r.result.notices) {
    const std::string message =
        fmt::format("in {} of {} frames, first at frame {}: {}", notice.frames, r.sequence.frames,
                    notice.first_frame, notice.text);
    fmt::print(stderr, "skinsim run: warning: {}\n", message);
    warnings.push_back(message);
  }
  const driver::FrameMsStats& s = r.result.stats;
  fmt::print(
      "sequence {}: {} frames at {:g} fps; frame ms p50 {:.3f}, p95 {:.3f}, p99 {:.3f}, max "
      "{:.3f} at frame {} ({:.3f} s); budget {:.1f} ms\n",
      r.sequence.name, r.sequence.frames, r.sequence.fps, s.p50, s.p95, s.p99, s.max, s.worst_frame,
      r.sequence.time_s(s.worst_frame), 1000.0 / r.sequence.fps);
  fmt::print(
      "emulated {} frames{} in {:.1f} s ({:.2f} frames/s on {} host threads); {} of {} passes "
      "replayed from earlier frames\n",
      r.sequence.frames, o.reference ? " and their references" : "", seconds,
      r.sequence.frames / seconds,
      o.device.threads > 0 ? o.device.threads
                           : static_cast<int>(std::thread::hardware_concurrency()),
      r.result.passes_replayed, r.result.passes_replayed + r.result.passes_rendered);
  const std::string title =
      fmt::format("{} on {}, {}x{}", scene.label(), device.name, config.width, config.height);
  if (o.charts) r.charts = driver::write_sequence_charts(r.sequence, r.result, title, out);
  if (!r.charts.note.empty())
    fmt::print(stderr, "skinsim run: no sequence charts: {}\n", r.charts.note);
  r.page =
      driver::write_sequence_page(out, kFramesDir, r.sequence, r.result, title, r.charts.written);
  if (!r.page.note.empty()) fmt::print(stderr, "skinsim run: note: {}\n", r.page.note);
  if (o.reference) {
    const nlohmann::json summary = driver::sequence_json(r.sequence, r.result);
    if (summary.contains("worst_quality")) {
      const nlohmann::json& q = summary["worst_quality"];
      fmt::print("quality vs each frame's reference: worst {} {:.4f} at frame {}\n",
                 q["metric"].get<std::string>(), q["value"].get<double>(), q["index"].get<int>());
    }
    if (summary.contains("temporal")) {
      const nlohmann::json& t = summary["temporal"];
      fmt::print(
          "temporal stability (FLIP between consecutive frames vs the reference's): mean error "
          "{:.4f}, worst {:.4f} from frame {}\n",
          t["mean_error"].get<double>(), t["max_error"].get<double>(),
          t["worst_step"]["index"].get<int>());
    }
  }
  fmt::print("the frame below is the worst one, frame {}\n", s.worst_frame);
  return r;
}

// Where the reference came from, when it was not rendered, and why a rendered one could not
// be kept for later runs.
void print_reference_source(const driver::FrameJobResult& r, const driver::FrameJob& job,
                            const std::string& out) {
  for (const std::string& discarded : r.reference_discarded) {
    fmt::print(stderr, "skinsim run: note: {}\n", discarded);
  }
  switch (r.reference_source) {
    case driver::ReferenceSource::kKept:
      fmt::print("reference: reused from {}/{} (same scene, reference knobs and build)\n", out,
                 driver::kRunReferenceImage);
      break;
    case driver::ReferenceSource::kStore:
      fmt::print(
          "reference: reused from the reference store {} (same scene, reference knobs and "
          "build; SKINSIM_CACHE_DIR=off renders it)\n",
          job.reference_store->dir().string());
      break;
    case driver::ReferenceSource::kRendered:
      if (!r.reference_not_stored.empty()) {
        fmt::print(stderr,
                   "skinsim run: note: the reference was not kept in the reference store {}: {}\n",
                   job.reference_store->dir().string(), r.reference_not_stored);
      }
      break;
  }
}

// The frame's job: the options' scene, knobs and reference; the scene's warnings are printed as
// they arise and kept for result.json's "warnings".
driver::FrameJob frame_job_for(const RunOptions& o, const gpu_model::DeviceProfile& device,
                               const pipeline::PipelineConfig& config,
                               std::vector<std::string>& warnings) {
  driver::FrameJob job;
  job.device = &device;
  job.config = config;
  job.scene = o.scene;
  job.scene.warn = [&warnings](const std::string& message) {
    fmt::print(stderr, "skinsim run: warning: {}\n", message);
    warnings.push_back(message);
  };
  job.threads = o.device.threads;
  job.reference = o.reference;
  job.previous_run = o.out;  // the run this one replaces: its reference may be this one's
  job.reference_store = driver::ReferenceStore::from_environment();
  return job;
}

// A truth file (--truth FILE), read before the frame's work so that a wrong one fails at once;
// a cached truth is found once the scene is built (cached_truth_for).
std::optional<driver::Truth> truth_from_file(const RunOptions& o,
                                             const pipeline::PipelineConfig& config) {
  if (!o.truth.empty()) driver::require_truth("--truth", o.truth);
  driver::require_cached_for_choice(o.truth, o.truth_choice);
  if (o.truth.empty() || o.truth == driver::kCachedTruth) return std::nullopt;
  return driver::truth_file("--truth", o.truth, config.width, config.height);
}

// What the run rendered: one frame, or a sequence whose worst frame stands for it in the
// single-frame outputs.
struct Rendered {
  driver::FrameJobResult frame_job;
  std::optional<SequenceRun> sequence;

  const driver::FrameResult& result() const {
    return sequence ? sequence->result.worst : frame_job.frame;
  }
  const pipeline::GpuScene& gpu_scene() const {
    return sequence ? *sequence->gpu_scene : *frame_job.gpu_scene;
  }
};

Rendered render(const RunOptions& o, const driver::FrameJob& job,
                const pipeline::PipelineConfig& config, const gpu_model::DeviceProfile& device,
                const std::filesystem::path& out, std::vector<std::string>& warnings) {
  Rendered r;
  if (o.sequence.empty()) {
    r.frame_job = driver::run_frame_job(job);
  } else {
    r.sequence = play_sequence(o, job.scene, config, device, out, warnings);
  }
  return r;
}

// frame.png, a sequence's frames, charts and page, the frame's intermediates, the BRDF LUT it
// read and its timeline; returns the names written, in that order.
std::vector<std::string> write_frame_files(const Rendered& r, const std::filesystem::path& out) {
  const driver::FrameResult& result = r.result();
  std::vector<std::string> written = {"frame.png"};
  if (r.sequence) {
    written.push_back(std::string(kFramesDir) + "/*.png");
    written.insert(written.end(), r.sequence->charts.written.begin(),
                   r.sequence->charts.written.end());
    written.insert(written.end(), r.sequence->page.written.begin(), r.sequence->page.written.end());
  }
  driver::write_png(result.output.frame, out / "frame.png");
  for (const pipeline::NamedTarget& t : result.output.intermediates) {
    driver::write_png(t.target, out / (t.name + ".png"), t.display_scale);
    written.push_back(t.name + ".png");
  }
  if (pipeline::reads_brdf_lut(result.config)) {
    pipeline::BrdfLutTexture::shared(result.config)->write_png((out / "brdf_lut.png").string());
    written.push_back("brdf_lut.png");
  }
  const std::vector<results::PassCost> passes = driver::pass_costs(result.timing);
  std::vector<std::string> pass_names;
  for (const results::PassCost& p : passes) pass_names.push_back(p.name);
  io::write_file_atomically((out / "timeline.svg").string(),
                            reports::timeline_svg(passes, pass_names));
  written.push_back("timeline.svg");
  return written;
}

// The reference, its skin mask and the FLIP error map, for a frame measured against its
// reference; the figures go on stdout and into the record.
void write_quality_files(const driver::FrameJobResult& frame_job, const driver::FrameJob& job,
                         const RunOptions& o, const std::filesystem::path& out,
                         driver::RunRecord& record, std::vector<std::string>& written) {
  image::save_png(frame_job.reference->image, out / driver::kRunReferenceImage);
  const std::string mask = driver::reference_mask_path(driver::kRunReferenceImage);
  image::save_mask_png(frame_job.reference->skin, out / mask);
  record.reference = frame_job.reference_marker;
  print_reference_source(frame_job, job, o.out);
  const driver::FrameQuality& q = *frame_job.quality;
  image::save_png(q.error_map, out / "error_flip.png");
  written.insert(written.end(), {driver::kRunReferenceImage, mask, "error_flip.png"});
  record.quality = &q;
  record.no_skin = frame_job.no_skin;
  if (q.has_skin_metrics()) {
    fmt::print("quality vs reference: skin PSNR {:.2f} dB, SSIM {:.4f}, FLIP {:.4f}\n",
               q.metrics.at("psnr_skin"), q.metrics.at("ssim_skin"), q.metrics.at("flip_skin"));
  } else {  // the frame is still measured; only the skin metrics do not exist
    fmt::print(
        "quality vs reference: skin metrics not available; frame PSNR {:.2f} dB, SSIM "
        "{:.4f}, FLIP {:.4f}\n",
        q.metrics.at("psnr_frame"), q.metrics.at("ssim_frame"), q.metrics.at("flip_frame"));
  }
}

// The run's line, the scene's scale, the frame's cost table and its range over the profile's
// uncertain figures.
void print_frame_summary(const RunOptions& o, const gpu_model::DeviceProfile& device,
                         const pipeline::PipelineConfig& config, const driver::FrameResult& result,
                         const nlohmann::json& json) {
  std::vector<std::string> knobs;
  for (const std::string& knob : pipeline::summary_knobs(result.config)) {
    if (!pipeline::knob_applies(result.config, knob)) continue;
    knobs.push_back(knob + " " + pipeline::get_config_field(result.config, knob));
  }
  fmt::print("skinsim run: {} with {} on {} ({}), {}x{}{}{}\n", o.scene.label(), config.technique,
             device.name, device.gpu, config.width, config.height, knobs.empty() ? "" : ", ",
             fmt::join(knobs, ", "));
  if (!o.scene.builtin()) {
    const nlohmann::json& scale = json["scene_scale"];
    fmt::print("scene scale: {:.4g} units/mm ({}); {}\n", scale["units_per_mm"].get<double>(),
               scale["source"].get<std::string>(), scale["summary"].get<std::string>());
  }
  fmt::print("{}", gpu_model::format_frame_table(result.timing));
  fmt::print("range {:.3f} to {:.3f} ms over the profile's {} uncertain figures together{}\n",
             result.range.low, result.range.high, result.range.figures,
             result.range.left_out
                 ? fmt::format(" ({} that change what the emulator counts are left out: "
                               "--sensitivity re-renders them)",
                               result.range.left_out)
                 : "");
  fmt::print("{}", gpu_model::frame_table_legend());
}

int run(const RunOptions& o) {
  const gpu_model::DeviceProfile device = load_device(o.device);
  const pipeline::PipelineConfig config = driver::resolve_config(o.config, device);
  // Checked before any work, so a bad --out fails fast; swapped in only if the run succeeds.
  io::RunDirectory run_directory(o.out);
  const std::filesystem::path& out = run_directory.staging();

  driver::RunRecord record;
  const driver::FrameJob job = frame_job_for(o, device, config, record.warnings);
  std::optional<driver::Truth> truth = truth_from_file(o, config);
  const Rendered r = render(o, job, config, device, out, record.warnings);
  const driver::FrameResult& result = r.result();
  if (o.truth == driver::kCachedTruth) {
    truth = driver::cached_truth(
        r.gpu_scene(), config, o.truth_choice, o.device.threads,
        [](const std::string& note) { fmt::print(stderr, "skinsim run: note: {}\n", note); });
  }

  std::vector<std::string> written = write_frame_files(r, out);
  record.device = device.name;
  record.scene = &r.gpu_scene().scene();
  if (r.sequence) record.sequence = driver::sequence_json(r.sequence->sequence, r.sequence->result);
  if (r.frame_job.quality) write_quality_files(r.frame_job, job, o, out, record, written);
  if (o.sensitivity) {
    const auto recount = [&](const gpu_model::DeviceProfile& varied) {
      return driver::run_frame(r.gpu_scene(), result.config, varied, o.device.threads)
          .output.passes;
    };
    record.sensitivity = gpu_model::sensitivity(result.output.passes, device, recount);
    fmt::print("\n{}", gpu_model::format_sensitivity_table(*record.sensitivity));
  }
  if (truth) record.truth = judge_with_truth(*truth, r.frame_job);
  const nlohmann::json json = driver::run_result_json(result, o.scene.label(), record);
  driver::write_result_json(json, out / "result.json");

  print_frame_summary(o, device, config, result, json);
  written.push_back("result.json");
  run_directory.commit();
  fmt::print("wrote {}/{{{}}}\n", o.out, fmt::join(written, ", "));
  if (r.sequence && r.sequence->charts.display_attempt_pending) {
    // Every file is written and closed; only the exit handlers are skipped, which would tear
    // down libX11 under the attempt still waiting for the display (display_check.h).
    std::fflush(nullptr);
    std::_Exit(0);
  }
  return 0;
}

}  // namespace

Command add_run_command(CLI::App& app) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand(
      "run", "Render one frame of the skin pipeline on the emulated GPU and model its cost");
  add_device_options(*cmd, options->device);
  add_scene_options(*cmd, options->scene);
  add_pipeline_options(*cmd, options->config);
  cmd->add_option("--out", options->out, "Output directory")->capture_default_str();
  cmd->add_flag("!--no-reference", options->reference,
                "Skip the reference frame and the quality metrics (faster)");
  CLI::Option* truth = cmd->add_option(
      "--truth", options->truth,
      "Also judge the frame and the reference against a path-traced truth: `cached` "
      "(the truth store's, rendered with Blender Cycles when missing), a linear "
      "EXR or PNG of the same view, or a `skinsim truth` directory of it (its samples, its "
      "floor) (docs/validation.md)");
  add_truth_choice_options(*cmd, options->truth_choice);
  cmd->add_flag("--sensitivity", options->sensitivity,
                "Also report how frame time moves over each uncertain device figure's range");
  CLI::Option* sequence =
      cmd->add_option("--sequence", options->sequence,
                      "Render a sequence of frames: push-in, head-turn, light-orbit or a sequence "
                      "file (.toml); the frame outputs are its worst frame's")
          ->excludes(truth);
  cmd->add_option("--frames", options->frames,
                  "Frames of the sequence (default: the sequence's own)")
      ->check(integer_in(1, driver::kMaxSequenceFrames))
      ->needs(sequence);
  cmd->add_option("--fps", options->fps,
                  "Frame rate of the sequence; its frame interval is the charts' budget line "
                  "(default: the sequence's own)")
      ->check(positive_real(1000.0))
      ->needs(sequence);
  cmd->add_flag("!--no-charts", options->charts,
                "Skip a sequence's VTK charts (no X display needed)");
  return [options] { return run(*options); };
}

}  // namespace skinsim::app
