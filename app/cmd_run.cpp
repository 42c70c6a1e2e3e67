// `skinsim run`: one frame of the skin pipeline on the emulated GPU, its images, counters
// and modelled timing.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <iostream>

#include "app/cli_options.h"
#include "app/commands.h"
#include "driver/frame_job.h"
#include "driver/frame_passes.h"
#include "driver/frame_quality.h"
#include "driver/images.h"
#include "driver/reference_cache.h"
#include "driver/result_json.h"
#include "driver/truth_judge.h"
#include "gpu_model/sensitivity.h"
#include "gpu_model/timing_json.h"
#include "gpu_model/timing_table.h"
#include "io/atomic_file.h"
#include "io/run_directory.h"
#include "pipeline/brdf_lut_texture.h"
#include "pipeline/technique.h"
#include "quality/json_value.h"
#include "reports/timeline_svg.h"

namespace skinsim::app {

namespace {

struct RunOptions {
  DeviceOptions device;
  driver::SceneSource scene;
  pipeline::PipelineConfig config;
  std::string out = "out";
  bool sensitivity = false;
  bool reference = true;
  std::string truth;  // --truth: "cached", a file, or none
};

// `--truth`: the frame and the reference judged by the path-traced truth beside the
// reference's figures (driver/truth_judge.h), for result.json's "truth".
nlohmann::json judge_with_truth(const driver::Truth& truth, const driver::FrameJobResult& r) {
  const quality::Mask* skin = r.reference ? &r.reference->skin : nullptr;
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

int run(const RunOptions& o) {
  const gpu_model::DeviceProfile device = load_device(o.device);
  const pipeline::PipelineConfig config = driver::resolve_config(o.config, device);
  // Checked before any work, so a bad --out fails fast; swapped in only if the run succeeds.
  io::RunDirectory run_directory(o.out);

  // Printed as they arise and kept for result.json's "warnings".
  std::vector<std::string> warnings;
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
  // A truth file is read before the frame's work, so a wrong one fails at once.
  if (!o.truth.empty()) driver::require_truth("--truth", o.truth);
  std::optional<driver::Truth> truth;
  if (!o.truth.empty() && o.truth != driver::kCachedTruth) {
    truth = driver::truth_file("--truth", o.truth, config.width, config.height);
  }
  const driver::FrameJobResult frame_job = driver::run_frame_job(job);
  const driver::FrameResult& result = frame_job.frame;
  if (o.truth == driver::kCachedTruth) {
    truth = driver::cached_truth(
        *frame_job.gpu_scene, config, o.device.threads,
        [](const std::string& note) { fmt::print(stderr, "skinsim run: note: {}\n", note); });
  }

  const std::filesystem::path& out = run_directory.staging();
  std::vector<std::string> written = {"frame.png"};
  driver::write_png(result.output.frame, out / "frame.png");
  for (const pipeline::NamedTarget& t : result.output.intermediates) {
    driver::write_png(t.target, out / (t.name + ".png"), t.display_scale);
    written.push_back(t.name + ".png");
  }
  if (pipeline::reads_brdf_lut(config)) {
    pipeline::BrdfLutTexture::shared(config)->write_png((out / "brdf_lut.png").string());
    written.push_back("brdf_lut.png");
  }

  const std::vector<reports::PassCost> passes = driver::pass_costs(result.timing);
  std::vector<std::string> pass_names;
  for (const reports::PassCost& p : passes) pass_names.push_back(p.name);
  io::write_file_atomically((out / "timeline.svg").string(),
                            reports::timeline_svg(passes, pass_names));
  written.push_back("timeline.svg");

  nlohmann::json json = driver::frame_result_json(result, o.scene.label());
  json["device"] = device.name;
  json["scene_scale"] = driver::scene_scale_json(frame_job.gpu_scene->scene());
  if (frame_job.quality) {
    quality::save_png(frame_job.reference->image, out / driver::kRunReferenceImage);
    const std::string mask = driver::reference_mask_path(driver::kRunReferenceImage);
    quality::save_mask_png(frame_job.reference->skin, out / mask);
    json["reference"] = frame_job.reference_marker;
    print_reference_source(frame_job, job, o.out);
    const driver::FrameQuality& q = *frame_job.quality;
    quality::save_png(q.error_map, out / "error_flip.png");
    written.insert(written.end(), {driver::kRunReferenceImage, mask, "error_flip.png"});
    nlohmann::json metrics = nlohmann::json::object();
    for (const auto& [name, value] : q.metrics) metrics[name] = quality::metric_to_json(value);
    if (q.has_skin_metrics()) {
      fmt::print("quality vs reference: skin PSNR {:.2f} dB, SSIM {:.4f}, FLIP {:.4f}\n",
                 q.metrics.at("psnr_skin"), q.metrics.at("ssim_skin"), q.metrics.at("flip_skin"));
    } else {  // the frame is still measured; only the skin metrics do not exist
      metrics["skin_metrics_unavailable"] = frame_job.no_skin;
      fmt::print(
          "quality vs reference: skin metrics not available; frame PSNR {:.2f} dB, SSIM "
          "{:.4f}, FLIP {:.4f}\n",
          q.metrics.at("psnr_frame"), q.metrics.at("ssim_frame"), q.metrics.at("flip_frame"));
    }
    json["quality"] = metrics;
  }
  if (o.sensitivity) {
    const auto recount = [&](const gpu_model::DeviceProfile& varied) {
      return driver::run_frame(*frame_job.gpu_scene, config, varied, o.device.threads)
          .output.passes;
    };
    const auto rows = gpu_model::sensitivity(result.output.passes, device, recount);
    json["sensitivity"] = gpu_model::to_json(rows);
    fmt::print("\n{}", gpu_model::format_sensitivity_table(rows));
  }
  if (truth) json["truth"] = judge_with_truth(*truth, frame_job);
  json["warnings"] = warnings;
  // Paths and names come from the user as raw bytes; JSON must be UTF-8, so invalid bytes are
  // written as U+FFFD rather than throwing after the frame has been rendered.
  io::write_file_atomically(
      (out / "result.json").string(),
      json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");

  std::vector<std::string> knobs;
  for (const std::string& knob : pipeline::summary_knobs(config)) {
    if (!pipeline::knob_applies(config, knob)) continue;
    knobs.push_back(knob + " " + pipeline::get_config_field(config, knob));
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
  written.push_back("result.json");
  run_directory.commit();
  fmt::print("wrote {}/{{{}}}\n", o.out, fmt::join(written, ", "));
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
  cmd->add_option("--truth", options->truth,
                  "Also judge the frame and the reference against a path-traced truth: `cached` "
                  "(the truth store's, rendered with Blender Cycles when missing) or a linear "
                  "EXR or PNG of the same view (docs/validation.md)");
  cmd->add_flag("--sensitivity", options->sensitivity,
                "Also report how frame time moves over each uncertain device figure's range");
  return [options] { return run(*options); };
}

}  // namespace skinsim::app
