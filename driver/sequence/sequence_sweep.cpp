#include "driver/sequence/sequence_sweep.h"

#include <fmt/format.h>

#include <algorithm>

#include "driver/frame/images.h"
#include "driver/sequence/sequence_video.h"
#include "scene/gltf_animation.h"

namespace skinsim::driver {

namespace {

// The frame-time statistics over the frames' modelled ms and over their fast and slow ends.
results::SequenceSummary summarise(const Sequence& sequence, const SequenceResult& r) {
  std::vector<double> base, low, high;
  for (const SequenceFrame& f : r.frames) {
    base.push_back(f.range.base);
    low.push_back(f.range.low);
    high.push_back(f.range.high);
  }
  const FrameMsStats b = frame_ms_stats(base), l = frame_ms_stats(low), h = frame_ms_stats(high);
  results::SequenceSummary s;
  s.name = sequence.name;
  s.frames = sequence.frames;
  s.fps = sequence.fps;
  s.shown_frame = shown_frame(sequence);
  s.p50 = {b.p50, l.p50, h.p50};
  s.p95 = {b.p95, l.p95, h.p95};
  s.max = {b.max, l.max, h.max};
  s.frame_ms = std::move(base);
  double sum = 0.0, worst = 0.0;
  int steps = 0;
  for (const SequenceFrame& f : r.frames) {
    if (!f.temporal) continue;
    sum += f.temporal->error();
    worst = std::max(worst, f.temporal->error());
    ++steps;
  }
  if (steps > 0) {
    s.temporal_mean_error = sum / steps;
    s.temporal_max_error = worst;
  }
  return s;
}

}  // namespace

int shown_frame(const Sequence& sequence) {
  return sequence.frames - 1;
}

nlohmann::json sequence_fingerprint(const Sequence& sequence) {
  nlohmann::json tracks = nlohmann::json::array();
  for (const SequenceTrack& t : sequence.tracks) {
    tracks.push_back(
        {{"knob", t.knob}, {"relative", t.relative}, {"from", t.from}, {"to", t.to}, {"by", t.by}});
  }
  nlohmann::json fingerprint = {{"name", sequence.name},
                                {"frames", sequence.frames},
                                {"fps", sequence.fps},
                                {"loops", sequence.loops},
                                {"tracks", tracks}};
  // The file's content is in the scene's fingerprint; which of its animations plays is here.
  if (sequence.animated) fingerprint["animation"] = sequence.animation_clip->name;
  return fingerprint;
}

PlayedConfig play_sweep_config(const pipeline::GpuScene& scene, const Sequence& sequence,
                               const pipeline::PipelineConfig& resolved,
                               const gpu_model::DeviceProfile& device, int threads,
                               sim::PassMemo& memo, const SequenceReferences& references,
                               const std::filesystem::path& dir, const std::string& id,
                               const SceneAtTime& animated) {
  const std::string frames_dir = "configs/" + id + "_frames";
  std::filesystem::remove_all(dir / frames_dir);  // an interrupted run's
  std::filesystem::create_directories(dir / frames_dir);
  PlayedConfig played;
  // Every frame's counters and timing (not its images): which one is at the p95 rank is
  // known only at the end.
  std::vector<FrameResult> costs;
  const auto sink = [&](int index, const FrameResult& frame) {
    write_png(frame.output.frame, dir / frames_dir / fmt::format("{:04d}.png", index));
    if (index == shown_frame(sequence)) played.shown_image = to_image(frame.output.frame);
    costs.push_back({frame.config, {}, frame.timing, frame.range});
    costs.back().output.passes = frame.output.passes;
    costs.back().output.decisions = frame.output.decisions;
  };
  const SequenceResult result =
      run_sequence(scene, sequence, resolved, device, threads, sink, references, &memo, animated);
  played.summary = summarise(sequence, result);
  const auto at_p95 = std::find_if(costs.begin(), costs.end(), [&](const FrameResult& f) {
    return f.timing.frame_ms == played.summary.p95.ms;
  });
  played.cost_frame = std::move(*at_p95);
  const std::string video = "configs/" + id + ".webm";
  const VideoOutcome encoded = encode_sequence_video(dir / frames_dir, sequence.fps, dir / video);
  if (encoded.encoded) {
    played.summary.video = video;
    std::filesystem::remove_all(dir / frames_dir);
  } else {
    played.summary.frames_dir = frames_dir;
    played.video_note = encoded.note;
  }
  return played;
}

}  // namespace skinsim::driver
