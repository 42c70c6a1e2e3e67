// `skinsim run --sequence`: bad input names the option; a short push-in writes its frames,
// the per-frame results and their distribution.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/app/run_skinsim.h"
#include "tests/app/slide_scene.h"
#include "tests/scene/gltf_fixture.h"
#include "tests/scoped_env.h"

namespace {

using skinsim::test::Result;
using skinsim::test::run;
using skinsim::test::slide_scene;

const std::string kSmallSequence = " --resolution 64x48 --head-triangles 2000 --texture-size 64";

std::filesystem::path seq_cli_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("skinsim_seq_cli_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(SequenceCli, BadSequenceFramesAndFpsExitTwoNamingTheOption) {
  const Result nope =
      run("run --sequence nope" + kSmallSequence + " --out /tmp/skinsim_seq_unused");
  EXPECT_EQ(nope.exit_code, 2) << nope.output;
  EXPECT_NE(nope.output.find("--sequence: unknown sequence 'nope'"), std::string::npos)
      << nope.output;
  const Result zero = run("run --sequence push-in --frames 0" + kSmallSequence);
  EXPECT_EQ(zero.exit_code, 2) << zero.output;
  EXPECT_NE(zero.output.find("--frames"), std::string::npos) << zero.output;
  const Result fps = run("run --sequence push-in --fps -5" + kSmallSequence);
  EXPECT_EQ(fps.exit_code, 2) << fps.output;
  EXPECT_NE(fps.output.find("--fps"), std::string::npos) << fps.output;
  const Result alone = run("run --frames 4" + kSmallSequence);
  EXPECT_EQ(alone.exit_code, 2) << alone.output;
  EXPECT_NE(alone.output.find("--frames requires --sequence"), std::string::npos) << alone.output;
  const Result both = run("run --sequence push-in --camera-distance 1" + kSmallSequence);
  EXPECT_EQ(both.exit_code, 2) << both.output;
  EXPECT_NE(both.output.find("camera_distance_m"), std::string::npos) << both.output;
}

TEST(SequenceCli, PushInWritesFramesAndTheDistribution) {
  const auto dir = seq_cli_dir("push_in");
  const Result r =
      run("run --sequence push-in --frames 4 --fps 24" + kSmallSequence + " --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("sequence push-in: 4 frames at 24 fps"), std::string::npos) << r.output;
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(std::filesystem::exists(dir / "frames" / ("000" + std::to_string(i) + ".png")));
  }
  std::ifstream in(dir / "result.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const nlohmann::json& s = j.at("sequence");
  ASSERT_EQ(s.at("per_frame").size(), 4u);
  double max = 0.0;
  int worst = -1;
  for (const nlohmann::json& f : s.at("per_frame")) {
    const double ms = f.at("frame_ms").get<double>();
    EXPECT_LE(f.at("frame_ms_range").at("low").get<double>(), ms);
    EXPECT_GE(f.at("frame_ms_range").at("high").get<double>(), ms);
    double passes = 0.0;
    for (const nlohmann::json& p : f.at("passes")) passes += p.at("ms").get<double>();
    EXPECT_NEAR(passes, ms, 1e-9 * ms);
    if (ms > max) {
      max = ms;
      worst = f.at("index").get<int>();
    }
  }
  EXPECT_EQ(s.at("frame_ms").at("max").get<double>(), max);
  EXPECT_EQ(s.at("frame_ms").at("worst_frame").at("index").get<int>(), worst);
  EXPECT_DOUBLE_EQ(s.at("frame_ms").at("worst_frame").at("time_s").get<double>(), worst / 24.0);
  // The single-frame outputs are the worst frame's.
  EXPECT_EQ(j.at("timing").at("frame_ms").get<double>(), max);
  EXPECT_EQ(s.at("per_frame").at(3).at("knobs").at("camera_distance_m"), "0.35");
  // With the reference (the default): each frame's quality, the temporal steps after the first.
  EXPECT_TRUE(s.at("per_frame").at(0).contains("quality"));
  EXPECT_FALSE(s.at("per_frame").at(0).contains("temporal"));
  EXPECT_TRUE(s.at("per_frame").at(1).at("temporal").contains("error"));
  EXPECT_TRUE(s.at("temporal").contains("mean_error"));
  EXPECT_TRUE(s.contains("worst_quality"));
}

TEST(SequenceCli, PageShowsTheVideoOrSaysWhyNot) {
  const auto dir = seq_cli_dir("video");
  const std::string args =
      "run --sequence head-turn --frames 2 --no-reference --no-charts" + kSmallSequence;
  const Result r = run(args + " --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_TRUE(std::filesystem::exists(dir / "sequence.webm")) << r.output;
  std::ifstream page(dir / "sequence.html");
  const std::string html((std::istreambuf_iterator<char>(page)), {});
  EXPECT_NE(html.find("<video src=\"sequence.webm\""), std::string::npos) << html;

  const auto bare = seq_cli_dir("no_video");
  {
    const skinsim::test::ScopedEnv no_ffmpeg("PATH", "/nonexistent");
    const Result n = run(args + " --out " + bare.string());
    ASSERT_EQ(n.exit_code, 0) << n.output;
    EXPECT_NE(n.output.find("ffmpeg is not installed"), std::string::npos) << n.output;
  }
  EXPECT_FALSE(std::filesystem::exists(bare / "sequence.webm"));
  EXPECT_TRUE(std::filesystem::exists(bare / "frames" / "0001.png"));
  std::ifstream bare_page(bare / "sequence.html");
  const std::string bare_html((std::istreambuf_iterator<char>(bare_page)), {});
  EXPECT_NE(bare_html.find("No video: ffmpeg is not installed"), std::string::npos) << bare_html;
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(SequenceCli, GltfAnimationDrivesTheFrames) {
  for (int animated : {0, 1}) {  // the quad moves, then the camera
    skinsim::scene::testing::GltfFixture f("seq_anim" + std::to_string(animated));
    const std::string scene = slide_scene(f, animated);
    const auto dir = f.dir() / "out";
    const Result r = run("run --scene " + scene + " --sequence animation:slide --fps 4" +
                         " --resolution 64x48 --out " + dir.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // 0 s to the last keyframe (1 s) at 4 fps: 5 frames.
    EXPECT_NE(r.output.find("sequence animation:slide: 5 frames at 4 fps"), std::string::npos)
        << r.output;
    std::ifstream in(dir / "result.json");
    const nlohmann::json s = nlohmann::json::parse(in).at("sequence");
    EXPECT_EQ(s.at("animation"), "slide");
    ASSERT_EQ(s.at("per_frame").size(), 5u);
    EXPECT_NE(read_bytes(dir / "frames" / "0000.png"), read_bytes(dir / "frames" / "0004.png"));
    EXPECT_GT(s.at("per_frame").at(1).at("temporal").at("reference_flip").get<double>(), 0.0);
  }
}

TEST(SequenceCli, BadGltfAnimationExitsTwoNamingTheField) {
  skinsim::scene::testing::GltfFixture f("seq_anim_bad");
  const std::string scene = slide_scene(f, 0);
  const Result missing =
      run("run --scene " + scene + " --sequence animation:walk" + kSmallSequence);
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find("no animation named 'walk' (there are: slide)"), std::string::npos)
      << missing.output;
  f.json()["animations"][0]["channels"][0]["sampler"] = 5;
  const std::string broken = f.write_gltf("broken");
  const Result sampler = run("run --scene " + broken + " --sequence animation" + kSmallSequence);
  EXPECT_EQ(sampler.exit_code, 2) << sampler.output;
  EXPECT_NE(sampler.output.find("animations[0].channels[0].sampler: index 5 out of range"),
            std::string::npos)
      << sampler.output;
  f.json()["animations"][0]["channels"][0]["sampler"] = 0;
  f.json()["meshes"][0]["weights"] = {1.0};
  const Result weights =
      run("run --scene " + f.write_gltf("weights") + " --sequence animation" + kSmallSequence);
  EXPECT_EQ(weights.exit_code, 2) << weights.output;
  EXPECT_NE(weights.output.find("meshes[0].weights: 1 weights for 0 morph targets"),
            std::string::npos)
      << weights.output;
  const Result builtin = run("run --sequence animation" + kSmallSequence);
  EXPECT_EQ(builtin.exit_code, 2) << builtin.output;
  EXPECT_NE(builtin.output.find("the built-in head has no animation"), std::string::npos)
      << builtin.output;
}

}  // namespace
