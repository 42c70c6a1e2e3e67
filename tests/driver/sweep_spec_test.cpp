// Sweep expansion: combinations, order, canonical values, ids, validation errors.
#include "driver/sweep/sweep_spec.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "scene/error.h"
#include "util/fingerprint.h"

namespace skinsim::driver {
namespace {

namespace fs = std::filesystem;

TEST(SweepSpec, DefaultSweepIsFourScalesByFourLuts) {
  const std::vector<SweepConfig> configs = expand_sweep(default_sweep_spec());
  ASSERT_EQ(configs.size(), 16u);
  // The first axis (scale) varies slowest, the last (lut) fastest.
  EXPECT_EQ(configs[0].id, "scale1_lut8x32");
  EXPECT_EQ(configs[1].id, "scale1_lut16x64");
  EXPECT_EQ(configs[4].id, "scale0.5_lut8x32");
  EXPECT_EQ(configs[15].id, "scale0.125_lut64x256");
  EXPECT_EQ(configs[15].label, "scale 0.125, lut 64x256");
  EXPECT_FLOAT_EQ(configs[15].config.mobile.scale, 0.125f);
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
  for (const SweepConfig& c : configs) EXPECT_FLOAT_EQ(c.config.mobile.scale, 0.5f);
}

TEST(SweepSpec, FixedKnobsApplyToEveryConfiguration) {
  SweepSpec spec = default_sweep_spec();
  spec.fixed.push_back({"blur_iterations", "3", "--set blur_iterations=3"});
  spec.fixed.push_back({"device", "iphone5", "--set device=iphone5"});
  for (const SweepConfig& c : expand_sweep(spec)) {
    EXPECT_EQ(c.config.mobile.blur_iterations, 3);
    EXPECT_EQ(c.device, "iphone5");
  }
}

TEST(SweepSpec, NoAxesIsOneDefaultConfiguration) {
  const std::vector<SweepConfig> configs = expand_sweep(SweepSpec{});
  ASSERT_EQ(configs.size(), 1u);
  EXPECT_EQ(configs[0].id, "default");
}

std::vector<std::string> ids_of(const std::vector<SweepConfig>& configs) {
  std::vector<std::string> ids;
  for (const SweepConfig& c : configs) ids.push_back(c.id);
  return ids;
}

TEST(SweepSpec, AnAxisATechniqueDoesNotUseRunsOnceForIt) {
  SweepSpec spec;
  set_axis(spec, "scale", {"1", "0.5", "0.25", "0.125"}, "--scales");
  set_axis(spec, "technique", {"mobile", "wrap"}, "--techniques");
  const std::vector<SweepConfig> configs = expand_sweep(spec);
  // 4 mobile + 1 wrap; wrap first appears with the first scale and keeps the default scale.
  EXPECT_EQ(ids_of(configs),
            (std::vector<std::string>{"scale1_mobile", "scale0.5_wrap", "scale0.5_mobile",
                                      "scale0.25_mobile", "scale0.125_mobile"}));
  const SweepConfig& wrap = configs[1];
  EXPECT_EQ(wrap.label, "technique wrap");
  EXPECT_EQ(wrap.swept, (std::vector<std::pair<std::string, std::string>>{{"technique", "wrap"}}));
  EXPECT_FLOAT_EQ(wrap.config.mobile.scale, pipeline::PipelineConfig{}.mobile.scale);
  EXPECT_EQ(configs[0].label, "scale 1, technique mobile");
  // The wrap frame is the one the full cross product ran as scale0.5_wrap: same id, same
  // fingerprint, so a sweep directory written before resumes it.
  EXPECT_EQ(config_fingerprint(wrap, scene_fingerprint(SceneSource{}), 64, 48)["knobs"]["scale"],
            "0.5");
}

TEST(SweepSpec, AnUnusedAxisKeepsTheFixedValue) {
  SweepSpec spec;
  spec.fixed.push_back({"scale", "0.25", "--set scale=0.25"});
  set_axis(spec, "scale", {"1", "0.5"}, "--scales");
  set_axis(spec, "technique", {"wrap", "burley"}, "--techniques");
  EXPECT_EQ(ids_of(expand_sweep(spec)),
            (std::vector<std::string>{"scale0.25_wrap", "scale0.25_burley"}));
}

TEST(SweepSpec, LutAxesExpandOnlyWhereTheSpecularModelReadsTheLut) {
  SweepSpec spec;
  set_axis(spec, "specular", {"ks_lut", "ggx"}, "test");
  set_axis(spec, "lut", {"8x32", "32x128", "64x256"}, "--luts");
  set_axis(spec, "lut_format", {"rgba8", "rgba16f"}, "--lut-formats");
  const std::vector<SweepConfig> configs = expand_sweep(spec);
  ASSERT_EQ(configs.size(), 3u * 2u + 1u);
  EXPECT_EQ(configs.back().id, "specularggx_lut32x128_rgba8");  // the defaults
  EXPECT_EQ(configs.back().label, "specular ggx");
}

TEST(SweepSpec, AllTechniquesOverTheDefaultAxes) {
  SweepSpec spec = default_sweep_spec();
  set_axis(spec, "technique", pipeline::technique_names(), "--techniques");
  const std::vector<SweepConfig> configs = expand_sweep(spec);
  std::map<std::string, int> per_technique;
  std::set<std::string> ids;
  for (const SweepConfig& c : configs) {
    ++per_technique[c.config.technique];
    ids.insert(c.id);
  }
  EXPECT_EQ(ids.size(), configs.size());
  // mobile: 4 scales x 4 LUTs; urp has its own specular (no BRDF LUT): 1; every other
  // technique reads the LUT but has no buffer: 4.
  for (const std::string& t : pipeline::technique_names()) {
    EXPECT_EQ(per_technique[t], t == "mobile" ? 16 : t == "urp" ? 1 : 4) << t;
  }
  EXPECT_EQ(per_technique.size(), pipeline::technique_names().size());
  EXPECT_TRUE(ids.count("scale0.5_lut16x64_texture-space"));
}

TEST(SweepSpec, UnusedAxisValuesAreStillValidated) {
  SweepSpec spec;
  set_axis(spec, "technique", {"wrap"}, "--techniques");
  set_axis(spec, "scale", {"0.5", "2"}, "--scales");
  try {
    expand_sweep(spec);
    FAIL() << "scale 2 accepted";
  } catch (const SweepError& e) {
    EXPECT_NE(std::string(e.what()).find("technique wrap, scale 2"), std::string::npos) << e.what();
  }
}

// `count` values of a float knob: first, first + step, ...
std::vector<std::string> float_values(int count, double first, double step) {
  std::vector<std::string> values;
  for (int i = 0; i < count; ++i) values.push_back(fmt::format("{}", first + step * i));
  return values;
}

TEST(SweepSpec, AHugeProductThatFoldsToTwoIsCountedWithoutEnumerating) {
  SweepSpec spec;
  set_axis(spec, "technique", {"lod", "ssss"}, "--techniques");  // use none of the axes below
  set_axis(spec, "scale", float_values(1000, 0.001, 0.001), "--scales");
  set_axis(spec, "normal_offset_mm", float_values(1000, 0.0, 0.01), "axes.normal_offset_mm");
  set_axis(spec, "blur_iterations", {"1", "2", "3", "4", "5", "6", "7", "8"}, "--blur-iterations");
  set_axis(spec, "lod_distance_m", float_values(12, 1.0, 1.0), "axes.lod_distance_m");
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(count_sweep_configs(spec), 2u);  // of 2 x 1000 x 1000 x 8 x 12 = 192 million
  const std::vector<SweepConfig> configs = expand_sweep(spec);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(configs.size(), 2u);
  EXPECT_EQ(configs[0].label, "technique lod");
  EXPECT_EQ(configs[1].label, "technique ssss");
  EXPECT_LT(seconds, 2.0);
}

TEST(SweepSpec, ASweepOverTheLimitIsRefusedNamingCountLimitAndOption) {
  SweepSpec spec;
  set_axis(spec, "technique", {"mobile"}, "--techniques");
  set_axis(spec, "scale", float_values(1000, 0.001, 0.001), "--scales");
  set_axis(spec, "normal_offset_mm", float_values(200, 0.0, 0.01), "axes.normal_offset_mm");
  set_axis(spec, "blur_iterations", {"1", "2", "3", "4", "5", "6", "7", "8"}, "--blur-iterations");
  EXPECT_EQ(count_sweep_configs(spec), 1600000u);
  try {
    expand_sweep(spec);
    FAIL() << "1.6 million configurations accepted";
  } catch (const SweepError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("1600000 configurations"), std::string::npos) << m;
    EXPECT_NE(m.find("limit of 10000"), std::string::npos) << m;
    EXPECT_NE(m.find("--max-configs 1600000"), std::string::npos) << m;
  }
  // Raising the limit is what --max-configs does; a small sweep passes under a small limit.
  SweepSpec small;
  set_axis(small, "scale", {"1", "0.5"}, "--scales");
  EXPECT_EQ(expand_sweep(small, 2).size(), 2u);
  EXPECT_THROW(expand_sweep(small, 1), SweepError);
}

TEST(SweepSpec, RowsKeepTheKnobsTheFrameUses) {
  SweepSpec spec;
  set_axis(spec, "technique", {"mobile", "wrap"}, "--techniques");
  set_axis(spec, "specular", {"ks_lut", "ggx"}, "test");
  for (const SweepConfig& c : expand_sweep(spec)) {
    const auto all = all_knobs(c, 64, 48);
    std::map<std::string, std::string> knobs(all.begin(), all.end());
    keep_used_knobs(c, knobs);
    const bool mobile = c.config.technique == "mobile";
    const bool lut = c.config.specular == pipeline::SpecularModel::kKsLut;
    EXPECT_EQ(knobs.count("scale"), mobile ? 1u : 0u) << c.id;
    EXPECT_EQ(knobs.count("wrap"), mobile ? 0u : 1u) << c.id;
    EXPECT_EQ(knobs.count("lut"), lut ? 1u : 0u) << c.id;
    for (const char* always : {"technique", "resolution", "specular", "device"}) {
      EXPECT_EQ(knobs.count(always), 1u) << c.id << " " << always;
    }
  }
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
  const nlohmann::json scene = scene_fingerprint(SceneSource{});
  const nlohmann::json a = config_fingerprint(configs[0], scene, 2048, 1536);
  EXPECT_EQ(a, config_fingerprint(configs[0], scene, 2048, 1536));
  EXPECT_NE(a, config_fingerprint(configs[1], scene, 2048, 1536));
  EXPECT_NE(a, config_fingerprint(configs[0], scene, 1024, 768));
  SceneSource other;
  other.head_triangles = 5000;
  EXPECT_NE(a, config_fingerprint(configs[0], scene_fingerprint(other), 2048, 1536));
  EXPECT_EQ(a["knobs"]["resolution"], "2048x1536");
  EXPECT_EQ(a["knobs"]["device"], "ipad4");
}

// An edited scan at the same path, or an edited buffer or image beside it, is another scene:
// results made from the old one must not be resumed.
TEST(SweepSpec, SceneFingerprintCoversTheFilesContent) {
  const fs::path dir = fs::path(::testing::TempDir()) / "scene_fingerprint";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name, std::ios::binary) << text;
  };
  const std::string gltf =
      R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "mesh.bin", "byteLength": 4}]})";
  write("head.gltf", gltf);
  write("mesh.bin", "abcd");
  SceneSource scene;
  scene.path = (dir / "head.gltf").string();
  const nlohmann::json before = scene_fingerprint(scene);
  EXPECT_EQ(before["label"], scene.path);
  EXPECT_EQ(scene_fingerprint(scene), before);

  write("mesh.bin", "abce");
  const nlohmann::json buffer_edited = scene_fingerprint(scene);
  EXPECT_NE(buffer_edited, before);
  write("mesh.bin", "abcd");
  EXPECT_EQ(scene_fingerprint(scene), before);
  write("head.gltf", gltf + " ");
  EXPECT_NE(scene_fingerprint(scene), before);

  fs::remove(dir / "mesh.bin");  // as loading it would: the file at fault, named
  try {
    scene_fingerprint(scene);
    ADD_FAILURE() << "a missing buffer was fingerprinted";
  } catch (const scene::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("mesh.bin"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(scene_fingerprint(SceneSource{}).contains("content"));  // the code makes it
}

// Reference file names and content fingerprints hash with FNV-1a 64 (util/fingerprint.h).
TEST(SweepSpec, FileNameHashIsFnv1a64) {
  EXPECT_EQ(fnv1a64_hex(""), "cbf29ce484222325");   // FNV-1a 64 offset basis
  EXPECT_EQ(fnv1a64_hex("a"), "af63dc4c8601ec8c");  // published FNV-1a test vector
}

}  // namespace
}  // namespace skinsim::driver
