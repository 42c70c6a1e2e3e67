#include "pipeline/technique.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "pipeline/config.h"

namespace skinsim::pipeline {

std::vector<std::string> technique_names() {
  std::vector<std::string> names;
  for (const TechniqueSpec* t : all_techniques()) names.push_back(t->name);
  return names;
}

const TechniqueSpec& find_technique(const std::string& name) {
  for (const TechniqueSpec* t : all_techniques()) {
    if (t->name == name) return *t;
  }
  throw ConfigError(
      fmt::format("technique: unknown '{}' (known: {})", name, fmt::join(technique_names(), ", ")));
}

std::vector<std::string> technique_knobs(const std::string& technique) {
  std::vector<std::string> names;
  for (const KnobSpec& k : find_technique(technique).knobs) names.push_back(k.name);
  return names;
}

bool knob_applies(const PipelineConfig& config, const std::string& knob) {
  const auto named = [&](const KnobSpec& k) { return k.name == knob; };
  const std::vector<KnobSpec>& common = common_knobs();
  const std::vector<KnobSpec>& own = find_technique(config.technique).knobs;
  auto it = std::find_if(common.begin(), common.end(), named);
  if (it == common.end()) {
    it = std::find_if(own.begin(), own.end(), named);
    if (it == own.end()) return false;
  }
  return !it->applies || it->applies(config);
}

std::vector<std::string> summary_knobs(const PipelineConfig& config) {
  std::vector<std::string> names = technique_knobs(config.technique);
  for (const char* shading : {"specular", "lut", "lut_format", "skin_precision"}) {
    if (knob_applies(config, shading)) names.emplace_back(shading);
  }
  return names;
}

bool uses_specular_knob(const PipelineConfig& config) {
  return !find_technique(config.technique).own_specular;
}

bool reads_brdf_lut(const PipelineConfig& config) {
  return uses_specular_knob(config) && config.specular == SpecularModel::kKsLut;
}

}  // namespace skinsim::pipeline
