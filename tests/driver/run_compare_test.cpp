// `skinsim compare` without rendering: run directories made by hand (a result.json and a
// frame.png), so every rule is checked in milliseconds; tests/driver/compare_test.sh runs the
// real command on real runs and sweeps.
#include "driver/sweep/run_compare.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "driver/sweep/result_values.h"
#include "image/image.h"
#include "io/atomic_file.h"
#include "io/read_file.h"
#include "tests/scratch_dir.h"

namespace skinsim::driver {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = testing::scratch_root("skinsim_compare") / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

nlohmann::json result(double frame_ms, double fragments, const std::string& lut) {
  return {{"config", {{"lut", lut}, {"scale", "0.5"}}},
          {"device", "ipad4"},
          {"scene", "builtin:default-head"},
          {"counters", {{{"name", "skin"}, {"renderer", {{"fragments_shaded", fragments}}}}}},
          {"timing",
           {{"frame_ms", frame_ms},
            {"passes", {{{"name", "blur_h"}, {"ms", 1.0}}, {{"name", "blur_h"}, {"ms", 2.0}}}}}}};
}

// A 64x64 grey frame; `square` paints a bright 16x16 square at (8, 8).
fs::path make_run(const std::string& name, const nlohmann::json& json, bool square = false) {
  const fs::path dir = scratch(name);
  io::write_file_atomically(dir / "result.json", json.dump());
  image::Image frame = image::Image::filled(64, 64, glm::vec3(0.4f));
  if (square) {
    for (int y = 8; y < 24; ++y) {
      for (int x = 8; x < 24; ++x) frame.at(x, y) = glm::vec3(1.0f);
    }
  }
  image::save_png(frame, dir / "frame.png");
  return dir;
}

TEST(ResultValues, NamesNumbersByPathAndRepeatedNamesByCount) {
  const NamedValues v = numeric_values(result(2.0, 100.0, "8x32"));
  EXPECT_EQ(v.at("timing.frame_ms"), 2.0);
  EXPECT_EQ(v.at("timing.passes.blur_h.ms"), 1.0);
  EXPECT_EQ(v.at("timing.passes.blur_h#2.ms"), 2.0);
  EXPECT_EQ(v.at("counters.skin.renderer.fragments_shaded"), 100.0);
  EXPECT_EQ(v.count("config.lut"), 0u);  // settings are compared as changes, not values
  nlohmann::json with_reference = result(2.0, 100.0, "8x32");
  with_reference["reference"] = {{"fingerprint", {{"scene", {{"head_triangles", 60000}}}}}};
  EXPECT_EQ(numeric_values(with_reference), v);  // what the reference was made from: settings
}

TEST(ResultValues, CountersAreExactAndModelledValuesHaveATolerance) {
  reports::ConfigDiff d;
  compare_values(numeric_values(result(2.0, 100.0, "8x32")),
                 numeric_values(result(2.001, 101.0, "8x32")), reports::Tolerances{}, d);
  ASSERT_EQ(d.moved.size(), 1u);  // 0.05% of frame time is within the default 0.1%
  EXPECT_EQ(d.moved[0].name, "counters.skin.renderer.fragments_shaded");
  EXPECT_EQ(d.moved[0].kind, "counter");
  EXPECT_DOUBLE_EQ(d.moved[0].relative_change(), 0.01);
  EXPECT_EQ(*d.frame_ms_a, 2.0);
  EXPECT_EQ(*d.frame_ms_b, 2.001);

  reports::Tolerances loose;
  loose.counter = 0.02;
  loose.modelled = 0.0;
  compare_values(numeric_values(result(2.0, 100.0, "8x32")),
                 numeric_values(result(2.001, 101.0, "8x32")), loose, d);
  ASSERT_EQ(d.moved.size(), 1u);
  EXPECT_EQ(d.moved[0].name, "timing.frame_ms");
}

// Two runs made alike are the same; one fragment more, or one pixel a step of 8 bits
// brighter, is not identical (the pixel is below FLIP's visibility, so not a verdict).
TEST(RunCompare, EqualRunsAreTheSameAndOneCountOrPixelApartAreNot) {
  const fs::path a = make_run("same_a", result(2.0, 100.0, "8x32"));
  const fs::path b = make_run("same_b", result(2.0, 100.0, "8x32"));
  const reports::Comparison c = compare_outputs(a, b, {}, {});
  EXPECT_EQ(c.kind, "run");
  EXPECT_FALSE(c.different());
  EXPECT_TRUE(c.changes.empty());
  ASSERT_TRUE(c.configs.at(0).image);
  EXPECT_TRUE(c.configs[0].image->identical);

  const fs::path count = make_run("same_count", result(2.0, 101.0, "8x32"));
  const reports::Comparison counted = compare_outputs(a, count, {}, {});
  EXPECT_TRUE(counted.different());
  ASSERT_EQ(counted.configs.at(0).moved.size(), 1u);
  EXPECT_EQ(counted.configs[0].moved[0].name, "counters.skin.renderer.fragments_shaded");

  const fs::path pixel = make_run("same_pixel", result(2.0, 100.0, "8x32"));
  image::Image frame = image::Image::filled(64, 64, glm::vec3(0.4f));
  frame.at(30, 30) = glm::vec3(0.4f + 1.0f / 255.0f);
  image::save_png(frame, pixel / "frame.png");
  const reports::Comparison pixelled = compare_outputs(a, pixel, {}, {});
  ASSERT_TRUE(pixelled.configs.at(0).image);
  EXPECT_FALSE(pixelled.configs[0].image->identical);
}

TEST(RunCompare, OneKnobNamedWhatMovedAndTheFramesVerdictWithCrops) {
  const fs::path a = make_run("knob_a", result(2.0, 100.0, "8x32"));
  const fs::path b = make_run("knob_b", result(3.0, 200.0, "32x128"), /*square=*/true);
  const fs::path out = scratch("knob_out");
  const reports::Comparison c = compare_outputs(a, b, {}, out);
  EXPECT_TRUE(c.different());
  ASSERT_EQ(c.changes.size(), 1u);
  EXPECT_EQ(c.changes[0].name, "lut");
  EXPECT_EQ(c.changes[0].a, "8x32");
  EXPECT_EQ(c.changes[0].b, "32x128");
  const reports::ConfigDiff& run = c.configs.at(0);
  ASSERT_EQ(run.moved.size(), 2u);  // largest relative change first
  EXPECT_EQ(run.moved[0].name, "counters.skin.renderer.fragments_shaded");
  EXPECT_EQ(run.moved[1].name, "timing.frame_ms");
  ASSERT_TRUE(run.image);
  EXPECT_TRUE(run.image->flip.visible) << run.image->flip.visible_px;  // 256 px, above 30
  EXPECT_EQ(run.image->a_image, "../knob_a/frame.png");
  ASSERT_FALSE(run.image->windows.empty());
  const results::CropWindow& w = run.image->windows[0];
  EXPECT_TRUE(w.x <= 8 && w.x + w.size >= 24) << w.x;  // the window holds the square
  for (const auto& [what, path] : w.images) EXPECT_TRUE(fs::exists(out / path)) << path;
  EXPECT_TRUE(fs::exists(out / run.image->difference_image));
  EXPECT_TRUE(fs::exists(out / c.colour_bar));
}

TEST(RunCompare, OtherImagesSayWhichPixelsMovedWithoutAVerdict) {
  const fs::path a = make_run("other_a", result(2.0, 100.0, "8x32"));
  const fs::path b = make_run("other_b", result(2.0, 100.0, "8x32"));
  image::Image irradiance = image::Image::filled(8, 8, glm::vec3(0.5f));
  image::save_png(irradiance, a / "irradiance.png");
  irradiance.at(3, 4) = glm::vec3(0.75f);
  image::save_png(irradiance, b / "irradiance.png");
  image::save_png(irradiance, a / "brdf_lut.png");
  const reports::Comparison c = compare_outputs(a, b, {}, {});
  EXPECT_FALSE(c.different());  // the frame and every value are the same
  const std::vector<reports::ImageChange>& images = c.configs.at(0).other_images;
  ASSERT_EQ(images.size(), 2u);  // sorted by name; frame.png is the verdict's
  EXPECT_EQ(images[0].name, "brdf_lut.png");
  EXPECT_TRUE(images[0].b_image.empty());
  EXPECT_EQ(images[1].name, "irradiance.png");
  EXPECT_EQ(images[1].differing_px, 1u);
  EXPECT_NEAR(images[1].max_difference, 0.25, 1.0 / 255.0);
}

TEST(RunCompare, BadInputNamesTheFile) {
  const fs::path a = make_run("bad_a", result(2.0, 100.0, "8x32"));
  const fs::path missing = scratch("bad_missing") / "nowhere";
  try {
    compare_outputs(a, missing, {}, {});
    FAIL();
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
  const fs::path corrupt = make_run("bad_corrupt", result(2.0, 100.0, "8x32"));
  io::write_file_atomically(corrupt / "result.json", "{\"config\": ");
  try {
    compare_outputs(a, corrupt, {}, {});
    FAIL();
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find((corrupt / "result.json").string()), std::string::npos)
        << e.what();
  }
  const fs::path no_frame = make_run("bad_no_frame", result(2.0, 100.0, "8x32"));
  fs::remove(no_frame / "frame.png");
  try {
    compare_outputs(a, no_frame, {}, {});
    FAIL();
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find((no_frame / "frame.png").string()), std::string::npos)
        << e.what();
  }
}

TEST(RunCompare, ARunAndASweepAreNotCompared) {
  const fs::path run = make_run("mixed_run", result(2.0, 100.0, "8x32"));
  const fs::path sweep = scratch("mixed_sweep");
  io::write_file_atomically(sweep / "results.json", "{}");
  try {
    compare_outputs(run, sweep, {}, {});
    FAIL();
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("is a run"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("is a sweep"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace skinsim::driver
