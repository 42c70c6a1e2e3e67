// Sweep expansion: combinations, order, canonical values, ids, validation errors.
#include <gtest/gtest.h>

#include <set>

#include "driver/sweep_spec.h"

namespace skinsim::driver {
namespace {

TEST(SweepSpec, DefaultSweepIsFourScalesByFourLuts) {
  const std::vector<SweepConfig> configs = expand_sweep(default_sweep_spec());
  ASSERT_EQ(configs.size(), 16u);
  // The first axis (scale) varies slowest, the last (lut) fastest.
  EXPECT_EQ(configs[0].id, "scale1_lut8x32");
  EXPECT_EQ(configs[1].id, "scale1_lut16x64");
  EXPECT_EQ(configs[4].id, "scale0.5_lut8x32");
  EXPECT_EQ(configs[15].id, "scale0.125_lut64x256");
  EXPECT_EQ(configs[15].label, "scale 0.125, lut 64x256");
  EXPECT_FLOAT_EQ(configs[15].config.buffer_scale, 0.125f);
  EXPECT_EQ(configs[15].config.lut_width, 64);
  EXPECT_EQ(configs[15].config.lut_height, 256);
  for (const SweepConfig& c : configs) EXPECT_EQ(c.device, "ipad4");
  std::set<std::string> ids;
  for (const SweepConfig& c : configs) ids.insert(c.id);
  EXPECT_EQ(ids.size(), configs.size());
}

TEST(SweepSpec, ValuesAreCanonicalisedAndIdsAreFileNameSafe) {
  SweepSpec spec;
  set_axis(spec, "scale", {"1.0", "0.50"}, "--scales");
  set_axis(spec, "device", {"profiles/my ipad.toml"}, "--devices");
  set_axis(spec, "lut_format", {"rgba16f"}, "--lut-formats");
  const std::vector<SweepConfig> configs = expand_sweep(spec);
  ASSERT_EQ(configs.size(), 2u);
  EXPECT_EQ(configs[0].swept[0].second, "1");
  EXPECT_EQ(configs[1].swept[0].second, "0.5");
  EXPECT_EQ(configs[1].id, "scale0.5_my-ipad_rgba16f");
  EXPECT_EQ(configs[1].device, "profiles/my ipad.toml");
}

TEST(SweepSpec, LaterAxisOfTheSameKnobReplacesTheEarlier) {
  SweepSpec spec = default_sweep_spec();
  set_axis(spec, "scale", {"0.5"}, "--scales");
  const std::vector<SweepConfig> configs = expand_sweep(spec);
  ASSERT_EQ(configs.size(), 4u);
  for (const SweepConfig& c : configs) EXPECT_FLOAT_EQ(c.config.buffer_scale, 0.5f);
}

TEST(SweepSpec, FixedKnobsApplyToEveryConfiguration) {
  SweepSpec spec = default_sweep_spec();
  spec.fixed.push_back({"blur_iterations", "3", "--set blur_iterations=3"});
  spec.fixed.push_back({"device", "iphone5", "--set device=iphone5"});
  for (const SweepConfig& c : expand_sweep(spec)) {
    EXPECT_EQ(c.config.blur_iterations, 3);
    EXPECT_EQ(c.device, "iphone5");
  }
}

TEST(SweepSpec, NoAxesIsOneDefaultConfiguration) {
  const std::vector<SweepConfig> configs = expand_sweep(SweepSpec{});
  ASSERT_EQ(configs.size(), 1u);
  EXPECT_EQ(configs[0].id, "default");
}

void expect_error(const SweepSpec& spec, const std::string& fragment) {
  try {
    expand_sweep(spec);
    FAIL() << "expected SweepError mentioning " << fragment;
  } catch (const SweepError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(SweepSpec, BadInputNamesTheOrigin) {
  SweepSpec spec;
  EXPECT_THROW(set_axis(spec, "colour", {"red"}, "--colours"), SweepError);
  try {
    set_axis(spec, "colour", {"red"}, "--colours");
  } catch (const SweepError& e) {
    EXPECT_NE(std::string(e.what()).find("--colours: unknown knob 'colour'"), std::string::npos);
  }
  EXPECT_THROW(set_axis(spec, "scale", {}, "--scales"), SweepError);

  SweepSpec bad_value;
  set_axis(bad_value, "lut", {"32x128", "fast"}, "--luts");
  expect_error(bad_value, "--luts: bad value 'fast'");

  SweepSpec twice;
  set_axis(twice, "scale", {"0.5", "0.50"}, "--scales");
  expect_error(twice, "--scales: value '0.50' given twice");

  SweepSpec out_of_range;  // parses, but PipelineConfig::validate refuses it
  set_axis(out_of_range, "scale", {"0.5", "2"}, "--scales");
  expect_error(out_of_range, "scale 2");

  SweepSpec bad_fixed;
  bad_fixed.fixed.push_back({"gamma", "linear", "--set gamma=linear"});
  expect_error(bad_fixed, "--set gamma=linear: bad value 'linear'");
}

TEST(SweepSpec, FingerprintCoversKnobsDeviceAndScene) {
  const std::vector<SweepConfig> configs = expand_sweep(default_sweep_spec());
  const SceneSource scene;
  const nlohmann::json a = config_fingerprint(configs[0], scene, 2048, 1536);
  EXPECT_EQ(a, config_fingerprint(configs[0], scene, 2048, 1536));
  EXPECT_NE(a, config_fingerprint(configs[1], scene, 2048, 1536));
  EXPECT_NE(a, config_fingerprint(configs[0], scene, 1024, 768));
  SceneSource other = scene;
  other.head_triangles = 5000;
  EXPECT_NE(a, config_fingerprint(configs[0], other, 2048, 1536));
  EXPECT_EQ(a["knobs"]["resolution"], "2048x1536");
  EXPECT_EQ(a["knobs"]["device"], "ipad4");
}

TEST(SweepSpec, ShortHashIsStable) {
  EXPECT_EQ(short_hash(""), "cbf29ce484222325");   // FNV-1a 64 offset basis
  EXPECT_EQ(short_hash("a"), "af63dc4c8601ec8c");  // published FNV-1a test vector
}

}  // namespace
}  // namespace skinsim::driver
