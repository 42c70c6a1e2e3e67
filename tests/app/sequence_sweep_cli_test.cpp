// `skinsim sweep --sequence`: every configuration plays the sequence; its row carries the
// frame-time distribution (the row's frame_ms is the p95), the temporal stability and the
// video (or the frames, without ffmpeg); resuming keys configurations by the sequence too. A
// sweep over a glTF animation keys each frame's reference by its pose.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tests/app/run_skinsim.h"
#include "tests/app/slide_scene.h"
#include "tests/scoped_env.h"

namespace {

using skinsim::test::Result;
using skinsim::test::run;

const std::string kSweep =
    "sweep --no-charts --techniques mobile --luts 8x32 --resolutions 64x48 "
    "--head-triangles 2000 --texture-size 64 --sequence push-in --fps 24";

std::filesystem::path seq_sweep_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("skinsim_seq_sweep_" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(SequenceSweepCli, RowsCarryTheDistributionAndResumeBySequence) {
  const auto dir = seq_sweep_dir("rows");
  const Result r = run(kSweep + " --scales 1,0.5 --frames 3 --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("2 computed"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("p95 frame time to the budget"), std::string::npos) << r.output;
  const nlohmann::json results = nlohmann::json::parse(read(dir / "results.json"));
  ASSERT_EQ(results.at("rows").size(), 2u);
  for (const nlohmann::json& row : results.at("rows")) {
    const nlohmann::json& s = row.at("sequence");
    EXPECT_EQ(s.at("name"), "push-in");
    EXPECT_EQ(s.at("frames"), 3);
    EXPECT_EQ(s.at("shown_frame"), 2);
    ASSERT_EQ(s.at("frame_ms").size(), 3u);
    // The row's frame time and range are the p95's: what the recommendation holds to budget.
    EXPECT_EQ(row.at("frame_ms"), s.at("frame_ms_p95").at("ms"));
    EXPECT_EQ(row.at("frame_ms_low"), s.at("frame_ms_p95").at("low"));
    EXPECT_EQ(row.at("frame_ms_high"), s.at("frame_ms_p95").at("high"));
    // Nearest rank of 3 frames: p50 is the 2nd smallest, p95 and max the largest.
    std::vector<double> ms = s.at("frame_ms").get<std::vector<double>>();
    std::sort(ms.begin(), ms.end());
    EXPECT_EQ(s.at("frame_ms_p50").at("ms").get<double>(), ms[1]);
    EXPECT_EQ(s.at("frame_ms_max").at("ms").get<double>(), ms[2]);
    EXPECT_LE(s.at("frame_ms_p95").at("low").get<double>(), ms[2]);
    EXPECT_GE(s.at("temporal_mean_error").get<double>(), 0.0);
    EXPECT_GE(s.at("temporal_max_error"), s.at("temporal_mean_error"));
  }
  const std::string csv = read(dir / "results.csv");
  EXPECT_NE(csv.find("frame_ms.p95,frame_ms.p95_low,frame_ms.p95_high"), std::string::npos);
  const std::string report = read(dir / "report.html");
  EXPECT_NE(report.find("Frames in motion: push-in"), std::string::npos);
  EXPECT_NE(report.find("p95 frame time to the 33.3 ms budget"), std::string::npos);

  const Result again = run(kSweep + " --scales 1,0.5 --frames 3 --out " + dir.string());
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("0 computed, 2 resumed"), std::string::npos) << again.output;
  // Another sequence (more frames) is another sweep: nothing of the first is taken for it.
  const Result longer = run(kSweep + " --scales 1,0.5 --frames 4 --out " + dir.string());
  ASSERT_EQ(longer.exit_code, 0) << longer.output;
  EXPECT_NE(longer.output.find("2 computed, 0 resumed"), std::string::npos) << longer.output;
  std::filesystem::remove_all(dir);
}

TEST(SequenceSweepCli, VideoWithFfmpegFramesWithout) {
  const auto with = seq_sweep_dir("video");
  const Result r = run(kSweep + " --frames 2 --scales 1 --out " + with.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json row = nlohmann::json::parse(read(with / "results.json")).at("rows").at(0);
  const std::string video = row.at("sequence").at("video");
  ASSERT_FALSE(video.empty()) << "is ffmpeg installed (scripts/install-deps.sh)?";
  EXPECT_EQ(read(with / video).substr(0, 4), "\x1a\x45\xdf\xa3");  // EBML: a WebM
  EXPECT_NE(read(with / "report.html").find("<video src=\"" + video), std::string::npos);
  for (const auto& entry : std::filesystem::directory_iterator(with / "configs")) {
    EXPECT_FALSE(entry.path().string().ends_with("_frames")) << "encoded, so not kept";
  }

  const auto without = seq_sweep_dir("no_video");
  {
    const skinsim::test::ScopedEnv no_ffmpeg("PATH", "/nonexistent");
    const Result n = run(kSweep + " --frames 2 --scales 1 --out " + without.string());
    ASSERT_EQ(n.exit_code, 0) << n.output;
    EXPECT_NE(n.output.find("ffmpeg is not installed"), std::string::npos) << n.output;
  }
  const nlohmann::json bare =
      nlohmann::json::parse(read(without / "results.json")).at("rows").at(0).at("sequence");
  EXPECT_EQ(bare.at("video"), "");
  const std::string frames = bare.at("frames_dir");
  EXPECT_TRUE(std::filesystem::exists(without / frames / "0000.png"));
  EXPECT_TRUE(std::filesystem::exists(without / frames / "0001.png"));
  EXPECT_NE(read(without / "report.html").find("no video (ffmpeg absent or failed)"),
            std::string::npos);
  std::filesystem::remove_all(with);
  std::filesystem::remove_all(without);
}

// The camera slides past the quad: every frame is another view, so each has its own reference
// (five kept in refs/, none shared between poses), and a second sweep resumes the finished one.
TEST(SequenceSweepCli, GltfAnimationKeysEachFramesReferenceByItsPose) {
  skinsim::scene::testing::GltfFixture f("seq_sweep_anim");
  const std::string scene = skinsim::test::slide_scene(f, 1);
  const auto dir = f.dir() / "sweep";
  const std::string args =
      "sweep --no-charts --techniques mobile --luts 8x32 --scales 1 --resolutions 64x48 --scene " +
      scene + " --sequence animation:slide --fps 4 --out " + dir.string();
  const Result r = run(args);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("1 computed"), std::string::npos) << r.output;
  const nlohmann::json row = nlohmann::json::parse(read(dir / "results.json")).at("rows").at(0);
  const nlohmann::json& s = row.at("sequence");
  EXPECT_EQ(s.at("name"), "animation:slide");
  ASSERT_EQ(s.at("frames"), 5);  // 0 s to 1 s at 4 fps
  EXPECT_EQ(row.at("frame_ms"), s.at("frame_ms_p95").at("ms"));
  // The reference moves with the camera, so the frames' steps are measured against its own.
  EXPECT_GE(s.at("temporal_max_error"), s.at("temporal_mean_error"));
  int references = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "refs")) {
    const std::string name = entry.path().filename().string();
    references += name.ends_with(".png") && !name.ends_with("_skin.png");
  }
  EXPECT_EQ(references, 5) << "one reference per pose";
  const std::string report = read(dir / "report.html");
  EXPECT_NE(report.find("Frames in motion: animation:slide"), std::string::npos);
  EXPECT_NE(report.find("<video src=\"" + s.at("video").get<std::string>()), std::string::npos);

  const Result again = run(args);
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("0 computed, 1 resumed"), std::string::npos) << again.output;
}

}  // namespace
