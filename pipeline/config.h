// Every knob of a skin pipeline run: one parameter set, settable from the CLI and sweep
// files, validated with messages that name the field.
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

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

// Where the pre-integrated shader gets surface curvature: baked offline per vertex
// (smoothed, stored in a UV-space texture) or from screen-space derivatives (noisy on
// low-poly meshes: constant per triangle).
enum class CurvatureSource { kVertex, kDerivatives };

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

// Size of the Burley shader's uniform tap array (each tap: a vec2 offset and an RGB weight,
// two uniform vectors; 64 taps fit the SGX's fragment uniform file).
inline constexpr int kMaxBurleySamples = 64;

// Size of the dipole shader's uniform tap arrays (a vec2 offset and an area per tap: one
// uniform vector).
inline constexpr int kMaxDipoleSamples = 64;
// Screen-space AO taps per pixel (urp).
inline constexpr int kMaxSsaoTaps = 32;

struct PipelineConfig {
  std::string technique = "mobile";  // a name from the registry (technique.h)
  // Integration (irradiance) buffer size per axis, as a fraction of the render resolution.
  float scale = 0.5f;
  int lut_width = 32;    // BRDF LUT: N.H axis
  int lut_height = 128;  // BRDF LUT: N.V axis
  sim::TexelFormat lut_format = sim::TexelFormat::kRGBA8;
  int blur_iterations = 1;
  // Standard deviation of the screen-space diffusion blur in millimetres on the skin; by
  // default derived from the six-Gaussian profile (diffusion.h).
  std::optional<float> blur_width_mm;
  float normal_offset_mm = 1.0f;  // irradiance-pass vertex push along the normal
  // Mobile blur: 0 = taps ignore depth (GPU Pro 5); > 0 = taps on a surface this many mm
  // nearer or farther than the centre fade out (the irradiance buffer's alpha carries depth).
  float blur_follow_mm = 0.0f;
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
  float lod_distance_m = 2.0f;  // beyond this camera distance the single-pass shader runs

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

  // Technique knobs (docs/techniques.md). Specular model of every technique's skin shader;
  // only ks_lut reads the BRDF LUT, so the lut and lut_format knobs matter only with it.
  SpecularModel specular = SpecularModel::kKsLut;
  // Default float precision of every technique's skin fragment shader (sim/program.h).
  sim::Precision skin_precision = sim::Precision::kHighp;
  int preintegrated_lut_width = 64;   // N.L axis
  int preintegrated_lut_height = 64;  // curvature axis
  CurvatureSource curvature = CurvatureSource::kVertex;
  float wrap = 0.5f;  // light-wrap amount w: diffuse = max(0, (N.L + w) / (1 + w))
  int burley_samples = 16;
  // Burley scattering distance d per channel (mm); by default fitted to the six-Gaussian
  // profile's mean scattering radius (techniques/kernels.h).
  std::optional<glm::vec3> burley_distance_mm;
  // Dipole taps per pixel, the centre included (the Unity article's 30 directions).
  int dipole_samples = 30;
  int texture_space_size = 1024;  // texture-space diffusion buffers, texels per axis
  bool shadow_scatter = true;     // pre-integrated: Penner's penumbra scattering
  // urp (the URP skin shader article): screen-space AO passes and their taps, the tiling pore
  // detail normals, the clear-coat layer.
  bool urp_ssao = true;
  int urp_ssao_taps = 12;
  bool urp_detail_normals = true;
  bool urp_clear_coat = true;

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
