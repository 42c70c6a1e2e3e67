#include "app/cli_options.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdlib>

#include "util/parse_number.h"

namespace skinsim::app {

std::string default_data_dir() {
  if (const char* env = std::getenv("SKINSIM_DATA_DIR"); env && *env) return env;
  return SKINSIM_DEFAULT_DATA_DIR;
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

CLI::Validator positive_real(double max) {
  return CLI::Validator(
      [max](std::string& text) -> std::string {
        const auto v = parse_real<double>(text);
        if (v && *v > 0.0 && *v <= max) return "";
        return fmt::format("expected a decimal number in (0, {:g}], got '{}'", max, text);
      },
      fmt::format("NUMBER in (0, {:g}]", max));
}

void add_device_options(CLI::App& cmd, DeviceOptions& o) {
  cmd.add_option("--device", o.device,
                 "Device profile: a shipped name (see `skinsim devices`) or a .toml file")
      ->capture_default_str();
  cmd.add_option("--data-dir", o.data_dir,
                 "Directory holding devices/*.toml (default: $SKINSIM_DATA_DIR or the source tree's data/)");
  cmd.add_option("--threads", o.threads,
                 "Host worker threads; 0 = all cores, 1 = synchronous (results are identical)")
      ->check(integer_in(0, 256))
      ->capture_default_str();
}

void add_scene_options(CLI::App& cmd, driver::SceneSource& s) {
  cmd.add_option("--scene", s.path,
                 "glTF 2.0 file (.gltf/.glb), or 'builtin' for the procedural head (default)");
  cmd.add_option("--head-triangles", s.head_triangles,
                 "Triangles of the built-in head mesh")
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
                 "World units per millimetre of the scene (default: glTF metres, 0.001)")
      ->check(positive_real(driver::kMaxUnitsPerMm));
}

namespace {

void knob(CLI::App& cmd, pipeline::PipelineConfig& config, const std::string& flag,
          const std::string& key, const std::string& help) {
  cmd.add_option_function<std::string>(
         flag,
         [&config, flag, key](const std::string& v) {
           try {
             pipeline::set_config_field(config, key, v);
           } catch (const pipeline::ConfigError& e) {  // name the option the user typed
             throw pipeline::ConfigError(fmt::format("{}: {}", flag, e.what()));
           }
         },
         help)
      ->default_str(pipeline::get_config_field(config, key));
}

}  // namespace

void add_pipeline_options(CLI::App& cmd, pipeline::PipelineConfig& c) {
  knob(cmd, c, "--technique", "technique",
       "Skin technique: " + fmt::format("{}", fmt::join(pipeline::technique_names(), ", ")));
  knob(cmd, c, "--scale", "scale", "Integration-buffer size per axis as a fraction of the frame, in (0,1]");
  knob(cmd, c, "--lut", "lut", "BRDF LUT size WxH (N.H x N.V), powers of two");
  knob(cmd, c, "--lut-format", "lut_format", "BRDF LUT texel format: rgba8 or rgba16f");
  knob(cmd, c, "--blur-iterations", "blur_iterations", "Separable blur iterations, 1..8");
  knob(cmd, c, "--blur-width-mm", "blur_width_mm",
       "Blur standard deviation on the skin in mm (default: from the six-Gaussian profile)");
  knob(cmd, c, "--normal-offset-mm", "normal_offset_mm", "Irradiance-pass vertex push along the normal, mm");
  knob(cmd, c, "--gamma", "gamma", "Skin gamma: 'square' (gamma 2.0, GPU Pro 5) or 'srgb'");
  knob(cmd, c, "--lobe1", "lobe1", "First specular lobe 'roughness,weight' (Beckmann m)");
  knob(cmd, c, "--lobe2", "lobe2", "Second specular lobe 'roughness,weight'");
  knob(cmd, c, "--specular-intensity", "specular_intensity", "Specular intensity rho_s");
  knob(cmd, c, "--resolution", "resolution", "Render resolution WxH (default: the device display)");
  knob(cmd, c, "--lod-distance", "lod_distance_m",
       "Camera distance in metres beyond which the single-pass LOD shader runs");
  knob(cmd, c, "--specular", "specular",
       "Specular model of the skin shaders (every technique): ks_lut (BRDF LUT), ks, ggx or "
       "dual_ggx");
  knob(cmd, c, "--preintegrated-lut", "preintegrated_lut",
       "Pre-integrated diffusion LUT size WxH (N.L x curvature), powers of two");
  knob(cmd, c, "--curvature", "curvature",
       "Pre-integrated curvature source: 'vertex' (baked, smoothed) or 'derivatives'");
  knob(cmd, c, "--wrap", "wrap", "Light-wrap amount w in [0,1] (wrap technique)");
  knob(cmd, c, "--burley-samples", "burley_samples", "Burley diffusion taps, 4..64");
  knob(cmd, c, "--burley-distance-mm", "burley_distance_mm",
       "Burley scattering distance 'r,g,b' in mm (default: fitted to the six-Gaussian profile)");
  knob(cmd, c, "--texture-space-size", "texture_space_size",
       "Texture-space diffusion buffer size per axis, power of two in [64, 4096]");
}

}  // namespace skinsim::app
