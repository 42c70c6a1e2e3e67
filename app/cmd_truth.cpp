// `skinsim truth`: an independent judge of image quality. Writes the scene skinsim renders
// (driver/truth/truth_scene.h), renders it with Blender Cycles' random-walk subsurface scattering
// (driver/truth/truth_render.h) to a linear OpenEXR, optionally a second time with another seed for
// the Monte Carlo noise floor, and with --compare the PSNR / SSIM / FLIP of a `skinsim run`'s
// frame and reference against it. docs/validation.md describes the judge.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "app/cli_options.h"
#include "app/commands.h"
#include "driver/frame/frame_job.h"
#include "driver/frame/reference_cache.h"
#include "driver/truth/truth_image.h"
#include "driver/truth/truth_render.h"
#include "driver/truth/truth_scene.h"
#include "driver/truth/truth_store.h"
#include "io/atomic_file.h"
#include "io/run_directory.h"
#include "util/user_error.h"

namespace skinsim::app {

namespace {

struct TruthOptions {
  DeviceOptions device;
  driver::SceneSource scene;
  pipeline::PipelineConfig config;
  driver::TruthSettings settings;
  int seed = 1;
  bool noise_floor = false;
  std::string compare;
  std::string out = "truth";
};

// What --compare reads from a `skinsim run` directory.
struct RunImages {
  image::Image frame, reference;
  image::Mask skin;
};

RunImages load_run(const std::filesystem::path& dir, int width, int height) {
  RunImages r;
  const std::filesystem::path reference = dir / driver::kRunReferenceImage;
  if (!std::filesystem::is_regular_file(reference)) {
    throw UserError("--compare " + dir.string() + ": no " + reference.filename().string() +
                    " (a `skinsim run` directory with its reference)");
  }
  r.frame = image::load_png(dir / "frame.png");
  r.reference = image::load_png(reference);
  r.skin = image::load_mask_png(driver::reference_mask_path(reference.string()));
  if (r.frame.width != width || r.frame.height != height) {
    throw UserError(fmt::format(
        "--compare {}: the run is {}x{}, the truth {}x{} (give truth the run's --resolution)",
        dir.string(), r.frame.width, r.frame.height, width, height));
  }
  return r;
}

// "PSNR 27.06 dB, SSIM 0.651, FLIP 0.117 (skin)": the skin's figures when there are any.
std::string figures(const nlohmann::json& m) {
  const nlohmann::json& s = m.contains("skin") ? m["skin"] : m["all"];
  const auto value = [](const nlohmann::json& v, const char* format) {
    return v.is_number() ? fmt::format(fmt::runtime(format), v.get<double>()) : v.dump();
  };
  return fmt::format("PSNR {} dB, SSIM {}, FLIP {}{}", value(s["psnr_db"], "{:.2f}"),
                     value(s["ssim"], "{:.3f}"), value(s["flip"], "{:.3f}"),
                     m.contains("skin") ? " (skin)" : "");
}

// A truth with its noise floor serves `run --truth cached` of the same view (truth_store.h).
void keep(const nlohmann::json& key, const driver::TruthImages& images) {
  const std::optional<driver::TruthStore> store = driver::TruthStore::from_environment();
  if (!store) return;
  const std::string why = store->keep(key, images);
  if (why.empty()) {
    fmt::print("skinsim truth: kept in the truth store as {}\n", store->marker(key).string());
  } else {
    fmt::print(stderr, "skinsim truth: note: the truth was not kept in {}: {}\n",
               store->dir().string(), why);
  }
}

int run_truth(const TruthOptions& o) {
  const gpu_model::DeviceProfile device = load_device(o.device);
  const pipeline::PipelineConfig config = driver::resolve_config(o.config, device);
  io::RunDirectory run_directory(o.out, "truth");
  const std::filesystem::path& out = run_directory.staging();

  // Read before the minutes of rendering, so a wrong directory fails at once.
  std::optional<RunImages> run;
  if (!o.compare.empty()) run = load_run(o.compare, config.width, config.height);

  driver::SceneSource source = o.scene;
  source.warn = [](const std::string& message) {
    fmt::print(stderr, "skinsim truth: warning: {}\n", message);
  };
  const scene::Scene scene = driver::load_scene(
      source, static_cast<float>(config.width) / static_cast<float>(config.height));
  const pipeline::GpuScene gpu_scene(scene);
  const nlohmann::json exported =
      driver::write_truth_scene(gpu_scene, config, o.settings, out / "scene");

  driver::TruthRender render{driver::blender_program(), driver::truth_script(), o.device.threads};
  const std::filesystem::path log = out / "blender.log";
  nlohmann::json result{
      {"scene", o.scene.label()},
      {"width", config.width},
      {"height", config.height},
      {"reference_profile", pipeline::reference_profile_name(config.reference_profile)},
      {"samples", o.settings.samples},
      {"seed", o.seed}};
  result["seconds"] = driver::render_truth(render, out / "scene", o.seed, out / "truth.exr", log);
  const image::Image truth =
      driver::display_image(driver::read_linear_image(out / "truth.exr", log));
  image::save_png(truth, out / "truth.png");

  const image::Mask* skin = run ? &run->skin : nullptr;
  if (o.noise_floor) {
    const int seed2 = o.seed + 1;
    const std::string name = fmt::format("truth_seed{}.exr", seed2);
    driver::render_truth(render, out / "scene", seed2, out / name, log);
    const image::Image other = driver::display_image(driver::read_linear_image(out / name, log));
    result["noise_floor"] = driver::truth_metrics(other, truth, skin);
    result["noise_floor"]["seed"] = seed2;
    // Two truths differ by twice one truth's noise variance, so an image without noise that
    // equals the expected truth still scores only 3.01 dB above the floor against one truth.
    for (auto& [mask, m] : result["noise_floor"].items()) {
      if (m.is_object() && m["psnr_db"].is_number()) {
        m["noise_free_psnr_ceiling_db"] = m["psnr_db"].get<double>() + 10.0 * std::log10(2.0);
      }
    }
    fmt::print("skinsim truth: noise floor (seed {} vs {}): {}\n", seed2, o.seed,
               figures(result["noise_floor"]));
    keep(driver::truth_key(exported, out / "scene", render.script, o.seed,
                           driver::blender_version(render.blender)),
         {truth, other});
  }
  if (run) {
    result["compare"] = o.compare;
    result["reference"] = driver::truth_metrics(run->reference, truth, skin);
    result["frame"] = driver::truth_metrics(run->frame, truth, skin);
    fmt::print("skinsim truth: reference vs truth: {}\n", figures(result["reference"]));
    fmt::print("skinsim truth: frame vs truth: {}\n", figures(result["frame"]));
  }
  io::write_file_atomically((out / "truth.json").string(), result.dump(2) + "\n");
  run_directory.commit();
  fmt::print(
      "skinsim truth: {}x{}, {} samples, seed {}: Cycles {:.1f} s; truth.exr, truth.png, "
      "truth.json in {}/\n",
      config.width, config.height, o.settings.samples, o.seed, result["seconds"].get<double>(),
      o.out);
  return 0;
}

}  // namespace

Command add_truth_command(CLI::App& app) {
  auto options = std::make_shared<TruthOptions>();
  CLI::App* cmd = app.add_subcommand(
      "truth",
      "Render the scene's ground truth with Blender Cycles (random-walk subsurface, path-traced "
      "shadows) to a linear OpenEXR, and judge a run's frame and reference against it");
  add_device_options(*cmd, options->device);
  add_scene_options(*cmd, options->scene);
  add_pipeline_options(*cmd, options->config);
  cmd->add_option("--samples", options->settings.samples, "Cycles samples per pixel")
      ->check(integer_in(1, 65536))
      ->capture_default_str();
  cmd->add_option("--seed", options->seed, "Cycles' random seed")
      ->check(integer_in(0, 1 << 30))
      ->capture_default_str();
  cmd->add_flag("--noise-floor", options->noise_floor,
                "Also render with the next seed and report the two truths' difference (the "
                "Monte Carlo noise floor every comparison against truth stands on), and keep "
                "both in the truth store for `--truth cached` (other --samples or --seed: "
                "with --truth-samples, --truth-seed)");
  cmd->add_option("--compare", options->compare,
                  "A `skinsim run` directory of the same scene and options: its frame's and "
                  "reference's PSNR/SSIM/FLIP against the truth, in truth.json");
  cmd->add_option("--out", options->out, "Output directory")->capture_default_str();
  return [options] { return run_truth(*options); };
}

}  // namespace skinsim::app
