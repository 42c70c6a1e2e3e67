#include "driver/sequence/sequence_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "driver/frame/frame_job.h"
#include "driver/frame/frame_passes.h"
#include "driver/frame/frame_quality.h"
#include "driver/frame/images.h"
#include "pipeline/reference/reference.h"
#include "quality/metrics.h"
#include "sim/pass_memo.h"
#include "util/check.h"

namespace skinsim::driver {

namespace {

std::vector<SequencePass> merged_passes(const gpu_model::FrameTiming& timing) {
  std::vector<SequencePass> merged;
  for (const results::PassCost& p : pass_costs(timing)) {
    auto same = std::find_if(merged.begin(), merged.end(),
                             [&p](const SequencePass& m) { return m.name == p.name; });
    if (same == merged.end()) {
      merged.push_back({p.name, p.ms});
    } else {
      same->ms += p.ms;
    }
  }
  return merged;
}

// The temporal error over the sequence: mean and worst step (none without a reference or with
// one frame).
std::optional<nlohmann::json> temporal_json(const Sequence& sequence, const SequenceResult& r) {
  double sum = 0.0, worst = -1.0;
  int steps = 0, worst_frame = 0;
  for (const SequenceFrame& f : r.frames) {
    if (!f.temporal) continue;
    sum += f.temporal->error();
    ++steps;
    if (f.temporal->error() > worst) {
      worst = f.temporal->error();
      worst_frame = f.index;
    }
  }
  if (steps == 0) return std::nullopt;
  return nlohmann::json{
      {"measure",
       "|FLIP(frame t, frame t-1) - FLIP(reference t, reference t-1)|, after Chu et al. 2020's "
       "tLP"},
      {"mean_error", sum / steps},
      {"max_error", worst},
      {"worst_step", {{"index", worst_frame}, {"time_s", sequence.time_s(worst_frame)}}}};
}

// The frame farthest from its reference: by FLIP over skin when every frame shows skin, else
// over the frame.
std::optional<nlohmann::json> worst_quality_json(const Sequence& sequence,
                                                 const SequenceResult& r) {
  const bool skin = std::all_of(r.frames.begin(), r.frames.end(), [](const SequenceFrame& f) {
    return f.quality.count("flip_skin");
  });
  const std::string metric = skin ? "flip_skin" : "flip_frame";
  const SequenceFrame* worst = nullptr;
  for (const SequenceFrame& f : r.frames) {
    if (!f.quality.count(metric)) continue;
    if (!worst || f.quality.at(metric) > worst->quality.at(metric)) worst = &f;
  }
  if (!worst) return std::nullopt;
  return nlohmann::json{{"metric", metric},
                        {"value", worst->quality.at(metric)},
                        {"index", worst->index},
                        {"time_s", sequence.time_s(worst->index)}};
}

}  // namespace

FrameMsStats frame_ms_stats(const std::vector<double>& frame_ms) {
  SKINSIM_CHECK(!frame_ms.empty());
  std::vector<double> sorted = frame_ms;
  std::sort(sorted.begin(), sorted.end());
  const auto nearest_rank = [&sorted](double p) {
    const auto n = static_cast<double>(sorted.size());
    const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * n));
    return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
  };
  FrameMsStats s;
  s.p50 = nearest_rank(50.0);
  s.p95 = nearest_rank(95.0);
  s.p99 = nearest_rank(99.0);
  s.max = sorted.back();
  s.mean =
      std::accumulate(frame_ms.begin(), frame_ms.end(), 0.0) / static_cast<double>(frame_ms.size());
  s.worst_frame =
      static_cast<int>(std::find(frame_ms.begin(), frame_ms.end(), s.max) - frame_ms.begin());
  return s;
}

SequenceReferences rendered_references(int threads) {
  return [threads](const pipeline::GpuScene& scene, const pipeline::PipelineConfig& frame,
                   double /*time_s*/) {
    return reference_images(pipeline::render_reference(scene, frame, threads));
  };
}

SequenceResult run_sequence(const pipeline::GpuScene& scene, const Sequence& sequence,
                            const pipeline::PipelineConfig& config,
                            const gpu_model::DeviceProfile& device, int threads,
                            const SequenceFrameSink& sink, const SequenceReferences& references,
                            sim::PassMemo* shared_memo, const SceneAtTime& animated) {
  if (sequence.animated && !animated) {
    throw SequenceError(fmt::format(
        "sequence '{}' plays the scene's glTF animation, but no animated scene was given",
        sequence.name));
  }
  SequenceResult r;
  // The previous frame and its reference, for the temporal step.
  std::optional<image::Image> previous_frame, previous_reference;
  std::optional<sim::PassMemo> own_memo;
  if (!shared_memo) own_memo.emplace(kPassMemoBytes);
  sim::PassMemo& memo = shared_memo ? *shared_memo : *own_memo;
  const sim::PassMemo::Stats before = memo.stats();
  std::vector<double> frame_ms;
  for (int i = 0; i < sequence.frames; ++i) {
    const pipeline::GpuScene& frame_scene = animated ? animated(sequence.time_s(i)) : scene;
    const pipeline::PipelineConfig frame_config =
        sequence_frame_config(sequence, i, config, frame_scene);
    FrameResult frame = run_frame(frame_scene, frame_config, device, threads, {}, &memo);
    SequenceFrame f;
    f.index = i;
    f.time_s = sequence.time_s(i);
    for (const SequenceTrack& t : sequence.tracks) {
      f.knobs[t.knob] = pipeline::get_config_field(frame_config, t.knob);
    }
    f.range = frame.range;
    f.passes = merged_passes(frame.timing);
    f.decisions = frame.output.decisions;
    for (const std::string& notice : frame.output.notices) {
      const std::string about = notice.substr(0, notice.find(':'));
      auto same = std::find_if(r.notices.begin(), r.notices.end(), [&about](const auto& n) {
        return n.text.substr(0, n.text.find(':')) == about;
      });
      if (same == r.notices.end()) {
        r.notices.push_back({i, 1, notice});
      } else {
        ++same->frames;
      }
    }
    if (references) {
      const ReferenceImages ref = references(frame_scene, frame_config, f.time_s);
      image::Image image = to_image(frame.output.frame);
      f.quality = evaluate_quality(image, ref).metrics;
      // Temporal stability after the tLP measure of Chu et al. ("Learning temporal coherence
      // via self-supervision for GAN-based video generation", ACM TOG 2020): the perceptual
      // difference between consecutive frames against the same for the ground truth, so
      // change the reference has (the camera moving) is not counted and flicker or crawling
      // noise it does not have is. FLIP stands in for their LPIPS.
      if (previous_frame) {
        f.temporal =
            SequenceFrame::TemporalStep{quality::flip(image, *previous_frame).mean,
                                        quality::flip(ref.image, *previous_reference).mean};
      }
      previous_frame = std::move(image);
      previous_reference = ref.image;
    }
    if (sink) sink(i, frame);
    frame_ms.push_back(frame.timing.frame_ms);
    if (i == 0 || frame.timing.frame_ms > r.worst.timing.frame_ms) r.worst = std::move(frame);
    r.frames.push_back(std::move(f));
  }
  r.stats = frame_ms_stats(frame_ms);
  r.passes_replayed = memo.stats().replayed - before.replayed;
  r.passes_rendered = memo.stats().rendered - before.rendered;
  return r;
}

nlohmann::json sequence_json(const Sequence& sequence, const SequenceResult& result) {
  nlohmann::json tracks = nlohmann::json::array();
  for (const SequenceTrack& t : sequence.tracks) {
    nlohmann::json track = {{"knob", t.knob}};
    if (t.relative) {
      track["by"] = t.by;
    } else {
      track["from"] = t.from;
      track["to"] = t.to;
    }
    tracks.push_back(track);
  }
  nlohmann::json frames = nlohmann::json::array();
  for (const SequenceFrame& f : result.frames) {
    nlohmann::json passes = nlohmann::json::array();
    for (const SequencePass& p : f.passes) passes.push_back({{"name", p.name}, {"ms", p.ms}});
    nlohmann::json frame = {{"index", f.index},
                            {"time_s", f.time_s},
                            {"knobs", f.knobs},
                            {"frame_ms", f.range.base},
                            {"frame_ms_range", {{"low", f.range.low}, {"high", f.range.high}}},
                            {"passes", passes},
                            {"technique", f.decisions}};
    if (!f.quality.empty()) frame["quality"] = f.quality;
    if (f.temporal) {
      frame["temporal"] = {{"frame_flip", f.temporal->frame_flip},
                           {"reference_flip", f.temporal->reference_flip},
                           {"error", f.temporal->error()}};
    }
    frames.push_back(std::move(frame));
  }
  const FrameMsStats& s = result.stats;
  nlohmann::json out = {
      {"name", sequence.name},
      {"frames", sequence.frames},
      {"fps", sequence.fps},
      {"loops", sequence.loops},
      {"duration_s", sequence.frames / sequence.fps},
      {"tracks", tracks},
      {"frame_ms",
       {{"p50", s.p50},
        {"p95", s.p95},
        {"p99", s.p99},
        {"max", s.max},
        {"mean", s.mean},
        {"percentiles", "nearest rank"},
        {"worst_frame", {{"index", s.worst_frame}, {"time_s", sequence.time_s(s.worst_frame)}}}}},
      {"reuse",
       {{"passes_replayed", result.passes_replayed}, {"passes_rendered", result.passes_rendered}}},
      {"per_frame", frames}};
  if (sequence.animated) out["animation"] = sequence.animation;
  if (const std::optional<nlohmann::json> t = temporal_json(sequence, result)) out["temporal"] = *t;
  if (const std::optional<nlohmann::json> q = worst_quality_json(sequence, result)) {
    out["worst_quality"] = *q;
  }
  return out;
}

}  // namespace skinsim::driver
