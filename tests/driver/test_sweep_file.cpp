// Sweep files: what they set, and errors that name the file, line and key.
#include <gtest/gtest.h>

#include "driver/sweep_file.h"

namespace skinsim::driver {
namespace {

TEST(SweepFile, ReadsAxesFixedSceneAndReport) {
  const SweepSpec spec = parse_sweep_text(R"(
[axes]
scale = [1, 0.5]
lut = ["8x32", "32x128"]
technique = "mobile"
[fixed]
blur_iterations = 2
device = "iphone5"
[scene]
path = "heads/lee.glb"
skin_materials = ["all"]
units_per_mm = 0.04
[report]
budget_ms = 16.7
)",
                                          "my.toml", "/data/sweeps");
  const std::vector<SweepConfig> configs = expand_sweep(spec);
  ASSERT_EQ(configs.size(), 4u);
  EXPECT_EQ(configs[3].id, "scale0.5_lut32x128_mobile");
  EXPECT_EQ(configs[3].config.blur_iterations, 2);
  EXPECT_EQ(configs[3].device, "iphone5");
  EXPECT_EQ(spec.scene.path, "/data/sweeps/heads/lee.glb");  // relative to the file
  EXPECT_EQ(spec.scene.skin_materials, std::vector<std::string>{"all"});
  EXPECT_FLOAT_EQ(spec.scene.units_per_mm, 0.04f);
  EXPECT_DOUBLE_EQ(spec.budget_ms, 16.7);
}

void expect_error(const std::string& text, const std::string& fragment) {
  try {
    parse_sweep_text(text, "s.toml", ".");
    FAIL() << "expected SweepError mentioning " << fragment;
  } catch (const SweepError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(SweepFile, ErrorsNameFileLineAndKey) {
  expect_error("[axes]\nscale = [1, 0.5\n", "s.toml:");  // TOML syntax
  expect_error("[axes]\nscale = [1, 0.5]\nlut = [\"big\"]\n",
               "s.toml:3: axes.lut: bad value 'big'");
  expect_error("[axes]\n\ncolour = [\"red\"]\n", "s.toml:3: axes.colour: unknown knob 'colour'");
  expect_error("[axes]\nscale = [true]\n", "s.toml:2: axes.scale: expected a string or a number");
  expect_error("[axes]\nscale = [1]\n[fixed]\ngamma = \"linear\"\n",
               "s.toml:4: fixed.gamma: bad value 'linear'");
  expect_error("[axes]\nscale = [1]\n[scene]\nhead_triangles = 10\n",
               "s.toml:4: scene.head_triangles: must be in [1000, 2000000]");
  expect_error("[axes]\nscale = [1]\n[scene]\ncamera = 1\n", "s.toml:4: scene.camera: unknown key");
  expect_error("[axez]\nscale = [1]\n", "s.toml:1: axez: unknown table");
  expect_error("[fixed]\nscale = 1\n", "s.toml: no [axes] given");
  expect_error("[report]\nbudget_ms = -1\n[axes]\nscale = [1]\n",
               "s.toml:2: report.budget_ms: must be > 0");
}

TEST(SweepFile, MissingFileIsNamed) {
  try {
    parse_sweep_file("/nonexistent/sweep.toml");
    FAIL();
  } catch (const SweepError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/sweep.toml: cannot open"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace skinsim::driver
