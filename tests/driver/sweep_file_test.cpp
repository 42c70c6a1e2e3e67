// Sweep files: what they set, and errors that name the file, line and key.
#include "driver/sweep/sweep_file.h"

#include <gtest/gtest.h>

#include "util/user_error.h"

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
skin_albedo = "194,150,130"
[report]
budget_ms = 16.7
)",
                                          "my.toml", "/data/sweeps");
  const std::vector<SweepConfig> configs = expand_sweep(spec);
  ASSERT_EQ(configs.size(), 4u);
  EXPECT_EQ(configs[3].id, "scale0.5_lut32x128_mobile");
  EXPECT_EQ(configs[3].config.mobile.blur_iterations, 2);
  EXPECT_EQ(configs[3].device, "iphone5");
  EXPECT_EQ(spec.scene.path, "/data/sweeps/heads/lee.glb");  // relative to the file
  EXPECT_EQ(spec.scene.skin_materials, std::vector<std::string>{"all"});
  EXPECT_FLOAT_EQ(spec.scene.units_per_mm, 0.04f);
  EXPECT_EQ(spec.scene.skin_albedo, "194,150,130");  // a colour, not a file beside it
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
               "s.toml:4: scene.head_triangles: 10 is out of range: must be in [1000, 2000000]");
  expect_error("[axes]\nscale = [1]\n[scene]\ncamera = 1\n", "s.toml:4: scene.camera: unknown key");
  expect_error("[axez]\nscale = [1]\n", "s.toml:1: axez: unknown table");
  expect_error("[fixed]\nscale = 1\n", "s.toml: no [axes] given");
  expect_error("[report]\nbudget_ms = -1\n[axes]\nscale = [1]\n",
               "s.toml:2: report.budget_ms: must be a finite number of milliseconds > 0");
}

// Hostile sweep files: each must end as a SweepError naming the file, line and key at fault.
TEST(SweepFile, AdversarialFilesAreRefusedNamingFileLineAndKey) {
  const struct {
    const char* what;
    std::string text;
    const char* fragment;
  } cases[] = {
      {"wrong type", "[axes]\nscale = {a = 1}\n",
       "s.toml:2: axes.scale: expected a string or a number"},
      {"table as a scalar", "axes = 3\n", "s.toml:1: axes: expected a table"},
      {"unknown key", "[axes]\nscale = [1]\n[report]\nbudget = 3\n",
       "s.toml:4: report.budget: unknown key"},
      {"empty axis", "[axes]\nscale = []\n", "s.toml:2: axes.scale: no values given"},
      {"duplicate value", "[axes]\nscale = [0.5, 0.50]\n",
       "s.toml:2: axes.scale: value '0.5' given twice"},
      {"huge head_triangles", "[axes]\nscale = [1]\n[scene]\nhead_triangles = 4294968296\n",
       "s.toml:4: scene.head_triangles: 4294968296 is out of range: must be in [1000, 2000000]"},
      {"negative texture_size",
       "[axes]\nscale = [1]\n[scene]\ntexture_size = -9223372036854775807\n",
       "s.toml:4: scene.texture_size: -9223372036854775807 is out of range"},
      {"huge integer knob", "[axes]\nblur_iterations = [4294967297]\n",
       "s.toml:2: axes.blur_iterations: bad value"},
      {"nan budget", "[axes]\nscale = [1]\n[report]\nbudget_ms = nan\n",
       "s.toml:4: report.budget_ms: must be a finite number of milliseconds > 0"},
      {"inf units", "[axes]\nscale = [1]\n[scene]\nunits_per_mm = -inf\n",
       "s.toml:4: scene.units_per_mm: must be > 0"},
      {"empty device", "[axes]\nscale = [1]\n[fixed]\ndevice = \"\"\n",
       "s.toml:4: fixed.device: empty device name"},
      {"empty knob value", "[axes]\nlut = [\"\"]\n", "s.toml:2: axes.lut: bad value ''"},
      {"non-UTF-8", "[axes]\nscale = [\"\xff\xfe\"]\n", "s.toml:2:"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    expect_error(c.text, c.fragment);
  }
}

TEST(SweepFile, RelativeDevicePathsAreRelativeToTheFile) {
  const SweepSpec spec = parse_sweep_text(
      "[axes]\ndevice = [\"ipad4\", \"profiles/mine.toml\", \"/abs/other.toml\"]\n", "my.toml",
      "/data/sweeps");
  ASSERT_EQ(spec.axes.size(), 1u);
  EXPECT_EQ(
      spec.axes[0].values,
      (std::vector<std::string>{"ipad4", "/data/sweeps/profiles/mine.toml", "/abs/other.toml"}));
  const SweepSpec fixed =
      parse_sweep_text("[axes]\nscale = [1]\n[fixed]\ndevice = \"d.toml\"\n", "my.toml", "/data");
  EXPECT_EQ(fixed.fixed.back().value, "/data/d.toml");
}

TEST(SweepFile, MissingFileIsNamed) {
  try {
    parse_sweep_file("/nonexistent/sweep.toml");
    FAIL();
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("sweep file /nonexistent/sweep.toml: No such file"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace skinsim::driver
