// The skin-rendering techniques skinsim compares. Each is a frame of render passes on the
// emulated GPU (frame.h dispatches); all are judged against the same reference.
// docs/techniques.md describes each one's passes, shaders and knobs.
#pragma once

#include <string>
#include <vector>

namespace skinsim::pipeline {

struct PipelineConfig;

enum class Technique {
  kMobile,         // GPU Pro 5 screen-space irradiance pipeline (the primary one)
  kLod,            // its single-pass distant-skin shader, at any distance
  kPreintegrated,  // Penner & Borshukov pre-integrated skin, single pass
  kWrap,           // light wrapping, single pass: the cheapest baseline
  kBurley,         // screen-space Burley normalized diffusion, importance-sampled taps
  kSsss,           // Jimenez separable screen-space SSS at full resolution
  kTextureSpace,   // d'Eon & Luebke texture-space diffusion: the expensive baseline
};

const char* technique_name(Technique technique);
// Parses a name from technique_names(); throws ConfigError listing the known ones.
Technique parse_technique(const std::string& name);
const std::vector<Technique>& all_techniques();
std::vector<std::string> technique_names();

// The knobs (set_config_field keys) a technique's frame depends on besides the ones every
// technique uses (technique, resolution, gamma, lobe1, lobe2, specular_intensity). A sweep
// that varies any other knob renders the same frame again for this technique.
const std::vector<std::string>& technique_knobs(Technique technique);

// Whether a frame rendered with `config` depends on `knob` (a set_config_field key): a knob
// every technique uses, or one of technique_knobs(config.technique) — lut and lut_format
// only with the ks_lut specular model, the one that reads the BRDF LUT.
bool knob_applies(const PipelineConfig& config, const std::string& knob);

}  // namespace skinsim::pipeline
