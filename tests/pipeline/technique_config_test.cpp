// The technique list and the technique knobs through set_config_field / get_config_field:
// round trips, defaults, and errors that name the key.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "pipeline/config.h"
#include "pipeline/shader_catalog.h"
#include "pipeline/technique.h"
#include "sim/counters.h"
#include "tests/pipeline/small_frames.h"

namespace skinsim::pipeline {
namespace {

TEST(TechniqueConfig, EveryTechniqueRoundTrips) {
  // The registry's order is its own (golden.coverage checks the set): the default first, each
  // name once.
  const std::vector<std::string> names = technique_names();
  ASSERT_FALSE(names.empty());
  EXPECT_EQ(names.front(), PipelineConfig{}.technique);
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
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

// TechniqueSpec::passes written out: "uv_blur_{1..2}_{h,v}" is uv_blur_1_h, uv_blur_1_v,
// uv_blur_2_h, uv_blur_2_v (the shell's brace expansion, leftmost slowest).
std::vector<std::string> expand_passes(const std::string& passes) {
  std::vector<std::string> items = {""};  // split at the commas outside braces
  int depth = 0;
  for (const char c : passes) {
    depth += c == '{' ? 1 : c == '}' ? -1 : 0;
    if (c == ',' && depth == 0) {
      items.emplace_back();
    } else if (c != ' ') {
      items.back() += c;
    }
  }
  std::vector<std::string> out;
  for (const std::string& item : items) {
    std::vector<std::string> names = {""};
    std::size_t at = 0;
    while (at < item.size()) {
      const std::size_t open = item.find('{', at);
      const std::string text = item.substr(at, open == std::string::npos ? open : open - at);
      for (std::string& n : names) n += text;
      if (open == std::string::npos) break;
      const std::size_t close = item.find('}', open);
      if (close == std::string::npos) throw std::invalid_argument("no } in '" + item + "'");
      const std::string inner = item.substr(open + 1, close - open - 1);
      std::vector<std::string> choices;
      if (const std::size_t dots = inner.find(".."); dots != std::string::npos) {
        for (int i = std::stoi(inner.substr(0, dots)); i <= std::stoi(inner.substr(dots + 2));
             ++i) {
          choices.push_back(std::to_string(i));
        }
      } else {
        std::stringstream alternatives(inner);
        for (std::string a; std::getline(alternatives, a, ',');) choices.push_back(a);
      }
      std::vector<std::string> grown;
      for (const std::string& n : names) {
        for (const std::string& c : choices) grown.push_back(n + c);
      }
      names = std::move(grown);
      at = close + 1;
    }
    out.insert(out.end(), names.begin(), names.end());
  }
  return out;
}

TEST(TechniqueConfig, PassListsExpandLikeTheShell) {
  EXPECT_EQ(expand_passes("a, b_{1..2}_{h,v}, c"),
            (std::vector<std::string>{"a", "b_1_h", "b_1_v", "b_2_h", "b_2_v", "c"}));
}

// Each technique's frame renders the passes its spec lists (after the frame's shadow pass,
// which every technique shares) and runs only programs `skinsim shaders` lists for it.
TEST(TechniqueConfig, EveryTechniqueRendersThroughItsSpec) {
  const std::vector<CatalogEntry> catalog = shader_catalog();
  for (const TechniqueSpec* t : all_techniques()) {
    EXPECT_EQ(&find_technique(t->name), t);
    EXPECT_FALSE(t->summary.empty()) << t->name;
    ASSERT_NE(t->render, nullptr) << t->name;
    const FrameOutput out = testing::render(testing::small_config(t->name));
    std::vector<std::string> rendered;
    for (const sim::PassCounters& p : out.passes) rendered.push_back(p.name);
    ASSERT_FALSE(rendered.empty()) << t->name;
    EXPECT_EQ(rendered.front(), "shadow") << t->name;
    rendered.erase(rendered.begin());
    EXPECT_EQ(rendered, expand_passes(t->passes)) << t->name;

    std::set<std::string> listed;  // in `skinsim shaders` as run by this technique
    for (const CatalogEntry& e : catalog) {
      if (std::count(e.techniques.begin(), e.techniques.end(), t->name)) {
        listed.insert(e.program.name);
      }
    }
    for (const sim::PassCounters& p : out.passes) {
      if (p.name == "shadow") continue;  // the frame's, with its own depth-only programs
      for (const sim::DrawCounters& d : p.draws) {
        for (const std::string& program : {d.vertex_program, d.fragment_program}) {
          EXPECT_TRUE(listed.count(program)) << t->name << " ran " << program << " in " << p.name;
        }
      }
    }
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
