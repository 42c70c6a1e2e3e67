// Every knob of a skin pipeline run: one parameter set, settable from the CLI and sweep
// files, validated with messages that name the field.
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "pipeline/techniques/burley/params.h"
#include "pipeline/techniques/dipole/params.h"
#include "pipeline/techniques/mobile/params.h"
#include "pipeline/techniques/preintegrated/params.h"
#include "pipeline/techniques/texture_space/params.h"
#include "pipeline/techniques/urp/params.h"
#include "pipeline/techniques/wrap/params.h"
#include "shading/op_profile.h"
#include "sim/texture.h"
#include "util/user_error.h"

namespace skinsim::pipeline {

class ConfigError : public UserError {
 public:
  using UserError::UserError;
};

enum class GammaMode { kSquare, kSrgb };  // gamma 2.0 (GPU Pro 5) or exact sRGB

// Specular model of the skin shaders (docs/skin-techniques.md section 2): the dual-lobe
// Kelemen/Szirmay-Kalos Beckmann from the BRDF LUT (one dependent read) or evaluated in ALU,
// a single GGX lobe, or two GGX lobes mixed in D.
enum class SpecularModel { kKsLut, kKs, kGgx, kDualGgx };

// Shadow-map fetch: one texel compared (nearest), or the 2x2 footprint compared and
// filtered by the hardware (EXT_shadow_samplers with a linear filter on iOS).
enum class ShadowFilter { kNearest, kPcf2x2 };

// The diffusion profile of the reference renderer (pipeline/reference/): d'Eon & Luebke's
// six Gaussians, or Jensen et al. 2001's dipole with their Skin1 measurements.
enum class ReferenceProfile { kSixGaussian, kDipole };

struct SpecularLobe {
  float roughness;  // Beckmann m
  float weight;
};

struct PipelineConfig {
  std::string technique = "mobile";  // a name from the registry (technique.h)
  int lut_width = 32;                // BRDF LUT: N.H axis
  int lut_height = 128;              // BRDF LUT: N.V axis
  sim::TexelFormat lut_format = sim::TexelFormat::kRGBA8;
  GammaMode gamma = GammaMode::kSquare;
  // Kelemen/Szirmay-Kalos dual lobe: d'Eon & Luebke (GPU Gems 3 ch. 14) use m = 0.3 for a
  // single lobe; the second, broader lobe models the oily layer's spread.
  SpecularLobe lobe1{0.3f, 0.85f};
  SpecularLobe lobe2{0.6f, 0.15f};
  float specular_intensity = 0.18f;  // rho_s, d'Eon & Luebke
  int width = 0;                     // render resolution; 0 = the device's display
  int height = 0;
  // MSAA samples per pixel of the framebuffer render (background, eyes, skin): 1, 2 or 4.
  int msaa = 1;

  // Light and framing (pipeline/lighting.h). Unset: the scene's own.
  std::optional<float> light_azimuth_deg;    // key light around the up axis, 0 = camera side
  std::optional<float> light_elevation_deg;  // key light above the horizon
  std::optional<float> back_light;           // back light strength, 1 = the studio rim light
  std::optional<float> camera_distance_m;    // camera to the head's centre (lighting.h)
  float camera_yaw_deg = 0.0f;               // camera orbit around the head's centre

  // The key light's shadow map (pipeline/frame_lights.h) and transmission (shaders/lights.h).
  bool shadows = true;
  int shadow_map_size = 1024;
  ShadowFilter shadow_filter = ShadowFilter::kPcf2x2;
  // Four filtered fetches: with one, a grazing receiver shows the map's texel steps (5-10 px
  // at 2048x1536 across the lips; docs/techniques.md, Light).
  int shadow_taps = 4;
  sim::TexelFormat shadow_depth = sim::TexelFormat::kDepth16;
  std::optional<glm::vec3> shadow_tint;  // light left in full shadow per channel; unset: none
  bool transmission = true;

  // The ground truth every technique is measured against (reference.h).
  ReferenceProfile reference_profile = ReferenceProfile::kSixGaussian;

  // Shading every technique shares (docs/techniques.md). Specular model of the skin shaders;
  // only ks_lut reads the BRDF LUT, so the lut and lut_format knobs matter only with it.
  SpecularModel specular = SpecularModel::kKsLut;
  // Default float precision of every technique's skin fragment shader (sim/program.h).
  sim::Precision skin_precision = sim::Precision::kHighp;

  // Each technique's own knobs, a struct in its folder (pipeline/techniques/<name>/params.h);
  // the knob rows of its TechniqueSpec bind to the fields.
  MobileParams mobile;
  PreintegratedParams preintegrated;
  WrapParams wrap;
  BurleyParams burley;
  TextureSpaceParams texture_space;
  DipoleParams dipole;
  UrpParams urp;

  // Throws ConfigError naming the knob when a value is out of range (each row of the knob
  // table checks its own; knobs.cpp).
  void validate() const;
};

// Sets one knob by name from text (a row of the knob table, knob.h), the single entry point
// for the CLI, sweep files and budget files. Throws ConfigError naming the key.
void set_config_field(PipelineConfig& config, const std::string& key, const std::string& value);
// The knob names set_config_field accepts (all_knobs() in order), and the value of each as text.
const std::vector<std::string>& config_field_names();
std::string get_config_field(const PipelineConfig& config, const std::string& key);

// "32x128" -> (32, 128); throws ConfigError mentioning `what` on bad input.
std::pair<int, int> parse_size(const std::string& text, const std::string& what);
GammaMode parse_gamma(const std::string& text);
const char* gamma_name(GammaMode mode);
sim::Precision parse_precision(const std::string& text);
const char* precision_name(sim::Precision precision);
SpecularModel parse_specular(const std::string& text);
const char* specular_name(SpecularModel model);
CurvatureSource parse_curvature(const std::string& text);
const char* curvature_name(CurvatureSource source);
ShadowFilter parse_shadow_filter(const std::string& text);
const char* shadow_filter_name(ShadowFilter filter);
sim::TexelFormat parse_shadow_depth(const std::string& text);
const char* shadow_depth_name(sim::TexelFormat format);
ReferenceProfile parse_reference_profile(const std::string& text);
const char* reference_profile_name(ReferenceProfile profile);
bool parse_switch(const std::string& text);  // on/off
const char* switch_name(bool on);

}  // namespace skinsim::pipeline
