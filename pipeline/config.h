// Every knob of a skin pipeline run: one parameter set, settable from the CLI and sweep
// files, validated with messages that name the field.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "pipeline/technique.h"
#include "sim/texture.h"

namespace skinsim::pipeline {

class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class GammaMode { kSquare, kSrgb };  // gamma 2.0 (GPU Pro 5) or exact sRGB

struct SpecularLobe {
  float roughness;  // Beckmann m
  float weight;
};

struct PipelineConfig {
  Technique technique = Technique::kMobile;
  // Integration (irradiance) buffer size per axis, as a fraction of the render resolution.
  float buffer_scale = 0.5f;
  int lut_width = 32;    // BRDF LUT: N.H axis
  int lut_height = 128;  // BRDF LUT: N.V axis
  sim::TexelFormat lut_format = sim::TexelFormat::kRGBA8;
  int blur_iterations = 1;
  // Standard deviation of the screen-space diffusion blur in millimetres on the skin; by
  // default derived from the six-Gaussian profile (diffusion.h).
  std::optional<float> blur_width_mm;
  float normal_offset_mm = 1.0f;  // irradiance-pass vertex push along the normal
  GammaMode gamma = GammaMode::kSquare;
  // Kelemen/Szirmay-Kalos dual lobe: d'Eon & Luebke (GPU Gems 3 ch. 14) use m = 0.3 for a
  // single lobe; the second, broader lobe models the oily layer's spread.
  SpecularLobe lobe1{0.3f, 0.85f};
  SpecularLobe lobe2{0.6f, 0.15f};
  float specular_intensity = 0.18f;  // rho_s, d'Eon & Luebke
  int width = 0;   // render resolution; 0 = the device's display
  int height = 0;
  float lod_distance_m = 2.0f;  // beyond this camera distance the single-pass shader runs

  // Throws ConfigError naming the field when a value is out of range.
  void validate() const;
};

// Sets one knob by name from text, the single entry point for the CLI, sweep files and
// budget files. Keys: technique, scale, lut, lut_format, blur_iterations, blur_width_mm,
// normal_offset_mm, gamma, lobe1, lobe2 ("roughness,weight"), specular_intensity,
// resolution ("WxH"), lod_distance_m. Throws ConfigError naming the key.
void set_config_field(PipelineConfig& config, const std::string& key, const std::string& value);
// The knob names set_config_field accepts, and the current value of each as text.
const std::vector<std::string>& config_field_names();
std::string get_config_field(const PipelineConfig& config, const std::string& key);

// "32x128" -> (32, 128); throws ConfigError mentioning `what` on bad input.
std::pair<int, int> parse_size(const std::string& text, const std::string& what);
GammaMode parse_gamma(const std::string& text);
const char* gamma_name(GammaMode mode);

}  // namespace skinsim::pipeline
