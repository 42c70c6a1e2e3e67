#include "app/cli_options.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdlib>

#include "gpu_model/profile_loader.h"
#include "pipeline/knob.h"
#include "util/parse_number.h"
#include "util/user_error.h"

namespace skinsim::app {

std::string default_data_dir() {
  if (const char* env = std::getenv("SKINSIM_DATA_DIR"); env && *env) return env;
  return SKINSIM_DEFAULT_DATA_DIR;
}

gpu_model::DeviceProfile load_device(const DeviceOptions& options) {
  return gpu_model::load_device_profile(
      options.device, options.data_dir.empty() ? default_data_dir() : options.data_dir);
}

CLI::Validator integer_in(int lo, int hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        const auto v = parse_integer<long long>(text);
        if (v && *v >= lo && *v <= hi) return "";
        return fmt::format("expected a decimal integer in [{}, {}], got '{}'", lo, hi, text);
      },
      fmt::format("INT in [{} - {}]", lo, hi));
}

namespace {

CLI::Validator real_in(double max, bool zero_allowed) {
  const char open = zero_allowed ? '[' : '(';
  return CLI::Validator(
      [max, zero_allowed, open](std::string& text) -> std::string {
        const auto v = parse_real<double>(text);
        if (v && (*v > 0.0 || (zero_allowed && *v == 0.0)) && *v <= max) return "";
        return fmt::format("expected a decimal number in {}0, {:g}], got '{}'", open, max, text);
      },
      fmt::format("NUMBER in {}0, {:g}]", open, max));
}

}  // namespace

CLI::Validator positive_real(double max) {
  return real_in(max, false);
}

CLI::Validator non_negative_real(double max) {
  return real_in(max, true);
}

void add_device_options(CLI::App& cmd, DeviceOptions& o) {
  cmd.add_option("--device", o.device,
                 "Device profile: a shipped name (see `skinsim devices`) or a .toml file")
      ->capture_default_str();
  cmd.add_option(
      "--data-dir", o.data_dir,
      "Directory holding devices/*.toml (default: $SKINSIM_DATA_DIR or the source tree's data/)");
  cmd.add_option("--threads", o.threads,
                 "Host worker threads; 0 = all cores, 1 = synchronous (results are identical)")
      ->check(integer_in(0, 256))
      ->capture_default_str();
}

void add_scene_options(CLI::App& cmd, driver::SceneSource& s) {
  cmd.add_option("--scene", s.path,
                 "glTF 2.0 file (.gltf/.glb), or 'builtin' for the procedural head (default)");
  cmd.add_option("--head-triangles", s.head_triangles, "Triangles of the built-in head mesh")
      ->check(integer_in(1000, 2000000))
      ->capture_default_str();
  cmd.add_option("--texture-size", s.texture_size, "Built-in skin texture edge in texels")
      ->check(integer_in(16, 4096))
      ->capture_default_str();
  cmd.add_option("--skin-materials", s.skin_materials,
                 "Material names to treat as skin ('all' = every material); default rule: "
                 "extras.skinsim.kind, else a name containing 'skin'")
      ->delimiter(',');
  cmd.add_option("--units-per-mm", s.units_per_mm,
                 "World units per millimetre of the scene (default: glTF's metres, 0.001, when "
                 "they give a plausible head; else sized from the head's crown-to-chin height "
                 "as a 225 mm head)")
      ->check(positive_real(driver::kMaxUnitsPerMm));
  cmd.add_option("--skin-albedo", s.skin_albedo,
                 "Skin colour of a scan: sRGB r,g,b (0-255; e.g. 194,150,130, the ColorChecker's "
                 "'light skin') or an image (sRGB, on the skin's TEXCOORD_0); default: the "
                 "file's base colour");
}

void add_truth_choice_options(CLI::App& cmd, driver::TruthChoice& choice) {
  const auto named = [&choice](const std::string&) { choice.named = true; };
  // The limits of `skinsim truth --samples` and --seed (app/cmd_truth.cpp).
  cmd.add_option("--truth-samples", choice.samples,
                 "With --truth cached: the truth rendered with this many Cycles samples (as "
                 "`skinsim truth --samples`); only looked up, never rendered")
      ->check(integer_in(1, 65536))
      ->each(named);
  cmd.add_option("--truth-seed", choice.seed,
                 "With --truth cached: the truth rendered with this seed and the next (as "
                 "`skinsim truth --seed`); only looked up, never rendered")
      ->check(integer_in(0, 1 << 30))
      ->each(named);
}

KnobAssignment parse_knob_assignment(const std::string& text, const std::string& option) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw UserError(fmt::format("{}: expected knob=value, got '{}'", option, text));
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

void add_pipeline_options(CLI::App& cmd, pipeline::PipelineConfig& config) {
  // One option per row of the knob table (pipeline/knob.h).
  for (const pipeline::KnobSpec& knob : pipeline::all_knobs()) {
    cmd.add_option_function<std::string>(
           knob.flag,
           [&config, &knob](const std::string& v) {
             try {
               knob.set(config, v);
             } catch (const pipeline::ConfigError& e) {  // name the option the user typed
               throw pipeline::ConfigError(fmt::format("{}: {}", knob.flag, e.what()));
             }
           },
           fmt::format("{} ({})", knob.help, knob.values))
        ->default_str(knob.get(config));
  }
  // CLI11 runs option callbacks in the order the options were added, not as typed, so a knob
  // given both ways has no "last one wins": it is refused.
  cmd.add_option_function<std::vector<std::string>>(
         "--set",
         [&cmd, &config](const std::vector<std::string>& assignments) {
           for (const std::string& text : assignments) {
             const auto [name, value] = parse_knob_assignment(text, "--set");
             const pipeline::KnobSpec& knob = pipeline::find_knob(name);
             if (cmd.get_option(knob.flag)->count() > 0) {
               throw UserError(
                   fmt::format("--set {}: {} is given too; give the knob once", text, knob.flag));
             }
             try {
               knob.set(config, value);
             } catch (const pipeline::ConfigError& e) {
               throw pipeline::ConfigError(fmt::format("--set {}: {}", text, e.what()));
             }
           }
         },
         "Set a knob by its name: knob=value (repeatable; names as in `skinsim knobs`, e.g. "
         "light_azimuth_deg=60)")
      ->type_name("KNOB=VALUE");
}

}  // namespace skinsim::app
