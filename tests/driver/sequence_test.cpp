// Sequences (driver/sequence/sequence.h, sequence_run.h): presets, sequence files, the frame-time
// distribution, and played sequences on a small built-in head.
#include "driver/sequence/sequence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "driver/sequence/sequence_run.h"
#include "gpu_model/profile_loader.h"
#include "tests/test_paths.h"

namespace skinsim::driver {
namespace {

TEST(Sequence, PresetsHaveTheirFramesAndRateAndTakeOverrides) {
  const Sequence push = load_sequence("push-in", 0, 0.0);
  EXPECT_EQ(push.frames, 60);
  EXPECT_EQ(push.fps, 30.0);
  ASSERT_EQ(push.tracks.size(), 1u);
  EXPECT_EQ(push.tracks[0].from, 2.8);
  EXPECT_EQ(push.tracks[0].to, 0.35);
  EXPECT_EQ(push.progress(0), 0.0);
  EXPECT_EQ(push.progress(59), 1.0);  // an open path ends at its end
  const Sequence orbit = load_sequence("light-orbit", 8, 24.0);
  EXPECT_EQ(orbit.frames, 8);
  EXPECT_EQ(orbit.fps, 24.0);
  EXPECT_EQ(orbit.progress(4), 0.5);  // a loop stops one step short of its start
  EXPECT_NEAR(orbit.time_s(6), 0.25, 1e-12);
}

TEST(Sequence, BadNamesAndCountsNameTheOption) {
  try {
    load_sequence("nope", 0, 0.0);
    FAIL();
  } catch (const SequenceError& e) {
    EXPECT_NE(std::string(e.what()).find("--sequence: unknown sequence 'nope'"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("push-in"), std::string::npos);
  }
  EXPECT_THROW(load_sequence("push-in", -1, 0.0), SequenceError);
  EXPECT_THROW(load_sequence("push-in", 0, std::nan("")), SequenceError);
}

TEST(Sequence, FileWithTracksOrAPreset) {
  const Sequence s = parse_sequence_file(R"(
[sequence]
name = "slow-turn"
frames = 5
fps = 10
[[sequence.track]]
knob = "camera_yaw_deg"
by = 40
[[sequence.track]]
knob = "camera_distance_m"
from = 1.0
to = 0.5
)",
                                         "turn.toml");
  EXPECT_EQ(s.name, "slow-turn");
  EXPECT_EQ(s.frames, 5);
  ASSERT_EQ(s.tracks.size(), 2u);
  EXPECT_TRUE(s.tracks[0].relative);
  EXPECT_FALSE(s.tracks[1].relative);
  const Sequence p =
      parse_sequence_file("[sequence]\npreset = \"push-in\"\nframes = 7\n", "p.toml");
  EXPECT_EQ(p.frames, 7);
  EXPECT_EQ(p.tracks.size(), 1u);
}

TEST(Sequence, ShippedSequenceFilesLoad) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(
           std::filesystem::path(test_paths::kDataDir) / "sequences")) {
    SCOPED_TRACE(entry.path().string());
    const Sequence s = load_sequence(entry.path().string(), 0, 0.0);
    EXPECT_NO_THROW(check_sequence(s, pipeline::PipelineConfig{}));
    ++files;
  }
  EXPECT_GT(files, 0);
}

TEST(Sequence, BadFilesNameFileLineAndField) {
  const auto message = [](const std::string& text) {
    try {
      parse_sequence_file(text, "s.toml");
    } catch (const SequenceError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(
      message("[sequence]\nframes = 0\npreset = \"push-in\"\n").find("s.toml:2: sequence.frames"),
      std::string::npos);
  EXPECT_NE(
      message("[sequence]\nframes = 3\nfps = 30\n[[sequence.track]]\nknob = \"camera_yaw_deg\"\n"
              "by = 1\nfrom = 2\n")
          .find("s.toml:4: [[sequence.track]] 'camera_yaw_deg': give either"),
      std::string::npos);
  EXPECT_NE(message("[sequence]\npreset = \"orbit\"\n").find("s.toml:2: sequence.preset"),
            std::string::npos);
  EXPECT_NE(
      message("[sequence]\npreset = \"push-in\"\nspeed = 2\n").find("sequence.speed: unknown key"),
      std::string::npos);
  EXPECT_NE(message("frames = 3\n").find("no [sequence] table"), std::string::npos);
}

TEST(Sequence, AbsoluteTrackOnAKnobTheRunSetIsRefused) {
  pipeline::PipelineConfig config;
  config.camera_distance_m = 1.0f;
  EXPECT_THROW(check_sequence(load_sequence("push-in", 0, 0.0), config), SequenceError);
  config.camera_distance_m.reset();
  EXPECT_NO_THROW(check_sequence(load_sequence("push-in", 0, 0.0), config));
  Sequence unknown = load_sequence("push-in", 0, 0.0);
  unknown.tracks[0].knob = "zoom";
  EXPECT_THROW(check_sequence(unknown, config), SequenceError);
}

TEST(Sequence, FrameMsStatsAreNearestRank) {
  std::vector<double> ms;
  for (int i = 1; i <= 20; ++i) ms.push_back(i == 7 ? 100.0 : i);  // one spike at frame 6
  const FrameMsStats s = frame_ms_stats(ms);
  EXPECT_EQ(s.p50, 11.0);   // rank ceil(0.5 * 20) = 10 of 1..6, 8..20, 100 sorted
  EXPECT_EQ(s.p95, 20.0);   // rank 19
  EXPECT_EQ(s.p99, 100.0);  // rank 20
  EXPECT_EQ(s.max, 100.0);
  EXPECT_EQ(s.worst_frame, 6);
}

class PlayedSequence : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    device_ =
        new gpu_model::DeviceProfile(gpu_model::load_device_profile("ipad4", test_paths::kDataDir));
    SceneSource source;
    source.head_triangles = 4000;
    source.texture_size = 128;
    scene_ = new scene::Scene(load_scene(source, 4.0f / 3.0f));
    gpu_scene_ = new pipeline::GpuScene(*scene_);
  }
  static void TearDownTestSuite() {
    delete gpu_scene_;
    delete scene_;
    delete device_;
  }
  static pipeline::PipelineConfig config() {
    pipeline::PipelineConfig c;
    c.width = 96;
    c.height = 72;
    c.shadow_map_size = 256;
    return resolve_config(c, *device_);
  }
  static inline gpu_model::DeviceProfile* device_ = nullptr;
  static inline scene::Scene* scene_ = nullptr;
  static inline pipeline::GpuScene* gpu_scene_ = nullptr;
};

TEST_F(PlayedSequence, IdenticalFramesGiveIdenticalResults) {
  Sequence still = parse_sequence_file(
      "[sequence]\nframes = 3\nfps = 30\n[[sequence.track]]\nknob = \"camera_distance_m\"\n"
      "from = 1.2\nto = 1.2\n",
      "still.toml");
  std::vector<std::vector<glm::vec4>> images;
  const SequenceResult r = run_sequence(
      *gpu_scene_, still, config(), *device_, 2,
      [&images](int, const FrameResult& f) { images.push_back(f.output.frame.pixels); });
  ASSERT_EQ(r.frames.size(), 3u);
  for (std::size_t i = 1; i < r.frames.size(); ++i) {
    EXPECT_EQ(r.frames[i].range.base, r.frames[0].range.base);
    EXPECT_EQ(r.frames[i].range.low, r.frames[0].range.low);
    EXPECT_EQ(r.frames[i].range.high, r.frames[0].range.high);
    ASSERT_EQ(r.frames[i].passes.size(), r.frames[0].passes.size());
    for (std::size_t p = 0; p < r.frames[i].passes.size(); ++p) {
      EXPECT_EQ(r.frames[i].passes[p].ms, r.frames[0].passes[p].ms);
    }
    EXPECT_EQ(images[i], images[0]) << "frame " << i;
  }
  EXPECT_EQ(r.stats.p50, r.stats.max);
  EXPECT_EQ(r.stats.worst_frame, 0);
  EXPECT_TRUE(r.frames[0].quality.empty());  // no reference asked for
  EXPECT_FALSE(r.frames[1].temporal);
  // Frames after the first replay every pass the memo keeps (those a later pass samples).
  EXPECT_GT(r.passes_replayed, 0);
}

TEST_F(PlayedSequence, IdenticalFramesHaveNoTemporalError) {
  const Sequence still = parse_sequence_file(
      "[sequence]\nframes = 3\nfps = 30\n[[sequence.track]]\nknob = \"camera_yaw_deg\"\n"
      "by = 0\n",
      "still.toml");
  const SequenceResult r =
      run_sequence(*gpu_scene_, still, config(), *device_, 2, {}, rendered_references(2));
  ASSERT_FALSE(r.frames[0].temporal);  // no previous frame
  for (std::size_t i = 1; i < r.frames.size(); ++i) {
    ASSERT_TRUE(r.frames[i].temporal);
    EXPECT_EQ(r.frames[i].temporal->frame_flip, 0.0);
    EXPECT_EQ(r.frames[i].temporal->reference_flip, 0.0);
    EXPECT_EQ(r.frames[i].quality, r.frames[0].quality);
  }
  EXPECT_GT(r.frames[0].quality.at("flip_skin"), 0.0);  // measured against a real reference
  const nlohmann::json j = sequence_json(still, r);
  EXPECT_EQ(j.at("temporal").at("mean_error"), 0.0);
  EXPECT_EQ(j.at("worst_quality").at("metric"), "flip_skin");
}

TEST_F(PlayedSequence, MovingFramesChangeAsTheReferenceDoes) {
  // A turning head: consecutive frames differ, and so do their references.
  const Sequence turn = load_sequence("head-turn", 3, 0.0);
  const SequenceResult r =
      run_sequence(*gpu_scene_, turn, config(), *device_, 2, {}, rendered_references(2));
  ASSERT_TRUE(r.frames[1].temporal);
  EXPECT_GT(r.frames[1].temporal->frame_flip, 0.0);
  EXPECT_GT(r.frames[1].temporal->reference_flip, 0.0);
  EXPECT_EQ(r.frames[1].temporal->error(),
            std::abs(r.frames[1].temporal->frame_flip - r.frames[1].temporal->reference_flip));
}

TEST_F(PlayedSequence, SameResultsForAnyThreadCount) {
  const Sequence turn = load_sequence("head-turn", 3, 0.0);
  const SequenceResult one = run_sequence(*gpu_scene_, turn, config(), *device_, 1);
  const SequenceResult three = run_sequence(*gpu_scene_, turn, config(), *device_, 3);
  for (std::size_t i = 0; i < one.frames.size(); ++i) {
    EXPECT_EQ(one.frames[i].range.base, three.frames[i].range.base) << "frame " << i;
    EXPECT_EQ(one.frames[i].knobs, three.frames[i].knobs);
  }
  EXPECT_EQ(one.frames.back().knobs.at("camera_yaw_deg"), "90");
}

TEST_F(PlayedSequence, PushInCrossesTheLodDistanceAtThePredictedFrame) {
  const Sequence push = load_sequence("push-in", 12, 0.0);
  const pipeline::PipelineConfig c = config();
  // The first frame whose camera is within lod_distance_m, from the preset's own path. Its
  // distance is to the head's centre and the LOD's to the skin box's centre; on the built-in
  // head they differ by far less than the path's step (0.22 m).
  const SequenceTrack& track = push.tracks.at(0);
  int predicted = -1;
  for (int i = 0; i < push.frames && predicted < 0; ++i) {
    const double distance = track.from + push.progress(i) * (track.to - track.from);
    if (distance <= c.mobile.lod_distance_m) predicted = i;
  }
  ASSERT_GT(predicted, 0);
  const SequenceResult r = run_sequence(*gpu_scene_, push, c, *device_, 2);
  for (int i = 0; i < push.frames; ++i) {
    EXPECT_EQ(r.frames[i].decisions.at("lod_shader"), i < predicted ? 1.0 : 0.0) << "frame " << i;
  }
  // The close-up frames cost more: the worst frame is the last, the closest.
  EXPECT_EQ(r.stats.worst_frame, push.frames - 1);
}

}  // namespace
}  // namespace skinsim::driver
