#include "driver/sequence_run.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "driver/frame_passes.h"
#include "driver/sweep_run.h"
#include "sim/pass_memo.h"
#include "util/check.h"

namespace skinsim::driver {

namespace {

std::vector<SequencePass> merged_passes(const gpu_model::FrameTiming& timing) {
  std::vector<SequencePass> merged;
  for (const reports::PassCost& p : pass_costs(timing)) {
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

SequenceResult run_sequence(const pipeline::GpuScene& scene, const Sequence& sequence,
                            const pipeline::PipelineConfig& config,
                            const gpu_model::DeviceProfile& device, int threads,
                            const SequenceFrameSink& sink) {
  SequenceResult r;
  sim::PassMemo memo(kPassMemoBytes);
  std::vector<double> frame_ms;
  for (int i = 0; i < sequence.frames; ++i) {
    const pipeline::PipelineConfig frame_config = sequence_frame_config(sequence, i, config, scene);
    FrameResult frame = run_frame(scene, frame_config, device, threads, {}, &memo);
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
    if (sink) sink(i, frame);
    frame_ms.push_back(frame.timing.frame_ms);
    if (i == 0 || frame.timing.frame_ms > r.worst.timing.frame_ms) r.worst = std::move(frame);
    r.frames.push_back(std::move(f));
  }
  r.stats = frame_ms_stats(frame_ms);
  r.passes_replayed = memo.stats().replayed;
  r.passes_rendered = memo.stats().rendered;
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
    frames.push_back({{"index", f.index},
                      {"time_s", f.time_s},
                      {"knobs", f.knobs},
                      {"frame_ms", f.range.base},
                      {"frame_ms_range", {{"low", f.range.low}, {"high", f.range.high}}},
                      {"passes", passes},
                      {"technique", f.decisions}});
  }
  const FrameMsStats& s = result.stats;
  return {
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
}

}  // namespace skinsim::driver
