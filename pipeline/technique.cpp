#include "pipeline/technique.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "pipeline/config.h"

namespace skinsim::pipeline {

const char* technique_name(Technique t) {
  switch (t) {
    case Technique::kMobile:
      return "mobile";
    case Technique::kLod:
      return "lod";
    case Technique::kPreintegrated:
      return "preintegrated";
    case Technique::kWrap:
      return "wrap";
    case Technique::kBurley:
      return "burley";
    case Technique::kSsss:
      return "ssss";
    case Technique::kTextureSpace:
      return "texture-space";
  }
  return "?";
}

const std::vector<Technique>& all_techniques() {
  static const std::vector<Technique> all = {
      Technique::kMobile, Technique::kLod,  Technique::kPreintegrated, Technique::kWrap,
      Technique::kBurley, Technique::kSsss, Technique::kTextureSpace};
  return all;
}

std::vector<std::string> technique_names() {
  std::vector<std::string> names;
  for (const Technique t : all_techniques()) names.emplace_back(technique_name(t));
  return names;
}

const std::vector<std::string>& technique_knobs(Technique t) {
  // Every skin shader takes the specular model; the BRDF LUT knobs matter only when it is
  // ks_lut, the one model that reads the LUT (knob_applies).
  static const std::vector<std::string> mobile = {"scale",          "lut",
                                                  "lut_format",     "blur_iterations",
                                                  "blur_width_mm",  "normal_offset_mm",
                                                  "lod_distance_m", "specular"};
  static const std::vector<std::string> lod = {"specular", "lut", "lut_format"};
  static const std::vector<std::string> preintegrated = {"preintegrated_lut", "curvature",
                                                         "specular", "lut", "lut_format"};
  static const std::vector<std::string> wrap = {"wrap", "specular", "lut", "lut_format"};
  static const std::vector<std::string> burley = {"burley_samples", "burley_distance_mm",
                                                  "specular", "lut", "lut_format"};
  static const std::vector<std::string> ssss = {"specular", "lut", "lut_format"};
  static const std::vector<std::string> texture_space = {"texture_space_size", "specular", "lut",
                                                         "lut_format"};
  switch (t) {
    case Technique::kMobile:
      return mobile;
    case Technique::kLod:
      return lod;
    case Technique::kPreintegrated:
      return preintegrated;
    case Technique::kWrap:
      return wrap;
    case Technique::kBurley:
      return burley;
    case Technique::kSsss:
      return ssss;
    case Technique::kTextureSpace:
      return texture_space;
  }
  return ssss;
}

bool knob_applies(const PipelineConfig& config, const std::string& knob) {
  static const std::vector<std::string> common = {"technique", "resolution", "gamma",
                                                  "lobe1",     "lobe2",      "specular_intensity"};
  const auto has = [&](const std::vector<std::string>& knobs) {
    return std::find(knobs.begin(), knobs.end(), knob) != knobs.end();
  };
  if (has(common)) return true;
  if ((knob == "lut" || knob == "lut_format") && config.specular != SpecularModel::kKsLut) {
    return false;
  }
  return has(technique_knobs(config.technique));
}

Technique parse_technique(const std::string& name) {
  for (const Technique t : all_techniques()) {
    if (name == technique_name(t)) return t;
  }
  throw ConfigError(
      fmt::format("technique: unknown '{}' (known: {})", name, fmt::join(technique_names(), ", ")));
}

}  // namespace skinsim::pipeline
