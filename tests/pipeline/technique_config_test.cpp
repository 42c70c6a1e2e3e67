// The technique list and the technique knobs through set_config_field / get_config_field:
// round trips, defaults, and errors that name the key.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "pipeline/config.h"
#include "pipeline/technique.h"

namespace skinsim::pipeline {
namespace {

TEST(TechniqueConfig, EveryTechniqueRoundTrips) {
  const std::vector<std::string> names = technique_names();
  EXPECT_EQ(names, (std::vector<std::string>{"mobile", "lod", "preintegrated", "wrap", "burley",
                                             "ssss", "texture-space", "dipole", "urp"}));
  for (const std::string& name : names) {
    PipelineConfig c;
    set_config_field(c, "technique", name);
    EXPECT_EQ(get_config_field(c, "technique"), name);
  }
}

TEST(TechniqueConfig, KnobsRoundTrip) {
  const std::vector<std::pair<std::string, std::string>> knobs = {
      {"specular", "ks"},
      {"specular", "ggx"},
      {"specular", "dual_ggx"},
      {"specular", "ks_lut"},
      {"preintegrated_lut", "128x32"},
      {"curvature", "derivatives"},
      {"curvature", "vertex"},
      {"wrap", "0.25"},
      {"burley_samples", "24"},
      {"burley_distance_mm", "1,0.5,0.25"},
      {"burley_distance_mm", "auto"},
      {"texture_space_size", "512"},
      {"dipole_samples", "12"},
      {"urp_ssao", "off"},
      {"urp_ssao_taps", "24"},
      {"urp_detail_normals", "off"},
      {"urp_clear_coat", "off"}};
  for (const auto& [key, value] : knobs) {
    PipelineConfig c;
    set_config_field(c, key, value);
    EXPECT_NO_THROW(c.validate()) << key;
    EXPECT_EQ(get_config_field(c, key), value) << key;
  }
  for (const char* key : {"specular", "preintegrated_lut", "curvature", "wrap", "burley_samples",
                          "burley_distance_mm", "texture_space_size"}) {
    const auto& names = config_field_names();
    EXPECT_NE(std::find(names.begin(), names.end(), key), names.end()) << key;
  }
}

TEST(TechniqueConfig, TechniqueKnobsAreKnownKeysOwnedByOneTechniqueOrSharedAsOneRow) {
  const auto& names = config_field_names();
  std::map<std::string, const KnobSpec*> owned;
  for (const TechniqueSpec* t : all_techniques()) {
    for (const KnobSpec& knob : t->knobs) {
      EXPECT_NE(std::find(names.begin(), names.end(), knob.name), names.end())
          << t->name << ": " << knob.name;
      const auto [it, first] = owned.emplace(knob.name, &knob);
      if (first) continue;
      // Only the pre-integrated LUT's size is shared (preintegrated and urp), from one builder.
      EXPECT_EQ(knob.name, "preintegrated_lut") << knob.name << " is owned by two techniques";
      EXPECT_EQ(knob.flag, it->second->flag);
      EXPECT_EQ(knob.help, it->second->help);
      EXPECT_EQ(knob.values, it->second->values);
    }
  }
  const auto urp = technique_knobs("urp");
  EXPECT_NE(std::find(urp.begin(), urp.end(), "preintegrated_lut"), urp.end());
  const auto mobile = technique_knobs("mobile");
  EXPECT_NE(std::find(mobile.begin(), mobile.end(), "scale"), mobile.end());
  const auto burley = technique_knobs("burley");
  EXPECT_EQ(std::find(burley.begin(), burley.end(), "scale"), burley.end());
  // Every name appears once in the table: common knobs and each technique's own.
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
}

TEST(TechniqueConfig, EveryTechniqueRendersThroughItsSpec) {
  for (const TechniqueSpec* t : all_techniques()) {
    EXPECT_NE(t->render, nullptr) << t->name;
    EXPECT_FALSE(t->shaders().empty()) << t->name;
    EXPECT_FALSE(t->summary.empty()) << t->name;
    EXPECT_EQ(&find_technique(t->name), t);
  }
  EXPECT_THROW(find_technique("sss"), ConfigError);
}

TEST(TechniqueConfig, KnobAppliesFollowsTheTechniqueAndTheSpecularModel) {
  PipelineConfig mobile, wrap;
  set_config_field(wrap, "technique", "wrap");
  for (const char* common : {"technique", "resolution", "gamma", "lobe1", "specular_intensity"}) {
    EXPECT_TRUE(knob_applies(mobile, common)) << common;
    EXPECT_TRUE(knob_applies(wrap, common)) << common;
  }
  EXPECT_TRUE(knob_applies(mobile, "scale"));
  EXPECT_FALSE(knob_applies(wrap, "scale"));
  EXPECT_TRUE(knob_applies(wrap, "wrap"));
  EXPECT_FALSE(knob_applies(mobile, "wrap"));
  for (PipelineConfig* c : {&mobile, &wrap}) {
    EXPECT_TRUE(knob_applies(*c, "specular"));
    EXPECT_TRUE(knob_applies(*c, "lut"));
    EXPECT_TRUE(knob_applies(*c, "lut_format"));
    set_config_field(*c, "specular", "ggx");  // no BRDF LUT read
    EXPECT_FALSE(knob_applies(*c, "lut"));
    EXPECT_FALSE(knob_applies(*c, "lut_format"));
  }
}

TEST(TechniqueConfig, EveryKnobAppliesToSomeTechnique) {
  for (const std::string& knob : config_field_names()) {
    bool used = false;
    for (const TechniqueSpec* t : all_techniques()) {
      PipelineConfig c;
      c.technique = t->name;
      used = used || knob_applies(c, knob);
    }
    EXPECT_TRUE(used) << knob;
  }
}

void expect_error(const std::string& key, const std::string& value, const std::string& needle) {
  PipelineConfig c;
  try {
    set_config_field(c, key, value);
    c.validate();
    ADD_FAILURE() << key << "=" << value << " accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(TechniqueConfig, BadValuesNameTheKey) {
  expect_error("technique", "sss", "technique");
  expect_error("specular", "phong", "specular");
  expect_error("preintegrated_lut", "64x63", "preintegrated_lut");
  expect_error("preintegrated_lut", "2x64", "preintegrated_lut");
  expect_error("curvature", "mesh", "curvature");
  expect_error("wrap", "1.5", "wrap");
  expect_error("wrap", "abc", "wrap");
  expect_error("burley_samples", "2", "burley_samples");
  expect_error("burley_samples", "65", "burley_samples");
  expect_error("dipole_samples", "3", "dipole_samples");
  expect_error("dipole_samples", "65", "dipole_samples");
  expect_error("urp_ssao_taps", "3", "urp_ssao_taps");
  expect_error("urp_ssao_taps", "33", "urp_ssao_taps");
  expect_error("urp_clear_coat", "maybe", "urp_clear_coat");
  expect_error("burley_distance_mm", "1,2", "burley_distance_mm");
  expect_error("burley_distance_mm", "1,0,1", "burley_distance_mm");
  expect_error("texture_space_size", "1000", "texture_space_size");
  expect_error("texture_space_size", "32", "texture_space_size");
}

}  // namespace
}  // namespace skinsim::pipeline
