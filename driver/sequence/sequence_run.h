// Playing a sequence (sequence.h): every frame rendered and timed as `run` does one
// (run_frame), the scene loaded once, and what does not change between frames reused: passes
// whose inputs are bit-identical to an earlier frame's (the shadow map while neither the light
// nor the head moved, the irradiance while only the light orbits nothing it sees) are
// replayed from a pass memo (sim/pass_memo.h), and the LUTs are baked once per process
// (pipeline::BrdfLutTexture::shared).
#pragma once

#include <cmath>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "driver/frame/frame_job.h"
#include "driver/frame/frame_quality.h"
#include "driver/sequence/sequence.h"

namespace skinsim::sim {
class PassMemo;
}

namespace skinsim::driver {

struct SequencePass {
  std::string name;  // same-named passes (blur iterations) merged
  double ms = 0.0;   // exposed share of the frame; the passes add up to frame_ms
};

struct SequenceFrame {
  int index = 0;
  double time_s = 0.0;
  std::map<std::string, std::string> knobs;  // the tracks' knobs as this frame set them
  gpu_model::FrameMsRange range;             // base = the modelled frame ms
  std::vector<SequencePass> passes;
  std::map<std::string, double> decisions;  // the technique's (pipeline::FrameOutput)
  // With a reference: the frame against its own reference (FrameQuality::metrics), and from
  // the second frame on its temporal stability (TemporalStep).
  std::map<std::string, double> quality;
  struct TemporalStep {
    double frame_flip = 0.0;      // FLIP mean between this frame and the previous one
    double reference_flip = 0.0;  // the same between their references
    double error() const { return std::abs(frame_flip - reference_flip); }
  };
  std::optional<TemporalStep> temporal;
};

// Frame-time distribution over a sequence. Percentiles are nearest-rank (the smallest frame
// time that at least p% of the frames do not exceed), so each is a frame that was modelled.
struct FrameMsStats {
  double p50 = 0.0, p95 = 0.0, p99 = 0.0, max = 0.0, mean = 0.0;
  int worst_frame = 0;  // the first frame at max
};
FrameMsStats frame_ms_stats(const std::vector<double>& frame_ms);

struct SequenceResult {
  std::vector<SequenceFrame> frames;
  FrameMsStats stats;
  FrameResult worst;  // the full result of stats.worst_frame
  int passes_replayed = 0;
  int passes_rendered = 0;
  // The technique's notices, grouped by what they are about (their text up to the first ':',
  // as the rest carries the frame's figures): the first frame's text, in order of appearance.
  struct Notice {
    int first_frame = 0;
    int frames = 0;  // how many frames raised it
    std::string text;
  };
  std::vector<Notice> notices;
};

// Called with each frame as it is finished, in order (to write its image, say).
using SequenceFrameSink = std::function<void(int index, const FrameResult&)>;

// Each frame's reference, for the frame's scene, configuration and time: rendered
// (rendered_references), or a sweep's, kept in its refs/ so configurations that share the
// reference knobs (and, in an animated sequence, the frame's time) share it.
using SequenceReferences = std::function<ReferenceImages(
    const pipeline::GpuScene& scene, const pipeline::PipelineConfig& frame, double time_s)>;
SequenceReferences rendered_references(int threads);

// The scene posed at a time (an animated glTF, sequence_animation.h); the reference it returns
// is valid until the next call.
using SceneAtTime = std::function<const pipeline::GpuScene&(double time_s)>;

// `config` resolved (resolve_config) and checked against the sequence (check_sequence).
// With `references`, each frame is measured against its reference, for its quality and the
// temporal stability: how much more (or less) the frame changes from the previous one than
// the reference does, in FLIP (sequence_run.cpp says why). `memo` (a sweep's, shared by its
// configurations) replaces the sequence's own. With `animated` (required by an animated
// sequence), each frame is of the scene it gives at the frame's time instead of `scene`.
SequenceResult run_sequence(const pipeline::GpuScene& scene, const Sequence& sequence,
                            const pipeline::PipelineConfig& config,
                            const gpu_model::DeviceProfile& device, int threads,
                            const SequenceFrameSink& sink = {},
                            const SequenceReferences& references = {},
                            sim::PassMemo* memo = nullptr, const SceneAtTime& animated = {});

// result.json's "sequence" section (docs/outputs.md).
nlohmann::json sequence_json(const Sequence& sequence, const SequenceResult& result);

}  // namespace skinsim::driver
