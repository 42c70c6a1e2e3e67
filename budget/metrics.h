// The metrics a budget can limit, measured from one frame: names, values and the per-pass
// facts (bottleneck, busy units) the failure messages explain them with.
//
//   frame.<kind>    kind: ms, dram_bytes, fragments_shaded, texture_miss_rate, alu_ops,
//                   texture_samples, fragments_depth_tested, triangles_in, energy_mj
//   <pass>.<kind>   the same kinds for one render pass of the frame (irradiance, blur_h, ...)
//   quality.<name>  psnr_skin, ssim_skin, flip_skin, psnr_frame, ssim_frame, flip_frame
//   frame_ms.<stat> a sequence's frame-time distribution: p50, p95, p99, max, mean (the
//                   budget's other metrics are then its worst frame's)
#pragma once

#include <map>
#include <string>
#include <vector>

#include "driver/frame/frame_job.h"

namespace skinsim::budget {

using MetricValues = std::map<std::string, double>;

// What the cost model said about one pass, for explaining why a limit moved.
struct PassFacts {
  std::string bottleneck;         // gpu_model::unit_name of the limiting unit
  double bottleneck_share = 0.0;  // that unit's busy time / pass time
  double share_of_frame = 0.0;    // the pass's exposed ms / frame ms
};

struct Measurement {
  MetricValues metrics;
  std::vector<std::string> passes;  // in submission order
  std::map<std::string, PassFacts> pass_facts;
  // A sequence's distribution in words (which frame is the worst, when), for failure messages.
  std::string sequence_summary;
};

// The per-pass and per-frame kinds ("ms", "dram_bytes", ...), and the quality names.
const std::vector<std::string>& counter_metric_kinds();
const std::vector<std::string>& quality_metric_names();
const std::vector<std::string>& sequence_metric_stats();  // p50, p95, p99, max, mean

// Whether a metric name is well formed (a known kind after the last '.', or a known quality
// metric); pass names can only be checked against a rendered frame.
bool is_known_metric_form(const std::string& metric);
bool is_quality_metric(const std::string& metric);
bool is_sequence_metric(const std::string& metric);  // frame_ms.<stat>
// "skin.ms" -> "skin"; "frame.ms" -> "frame"; "quality.psnr_skin" -> "quality".
std::string metric_scope(const std::string& metric);
// "skin.ms" -> "ms".
std::string metric_kind(const std::string& metric);

// Counter and timing metrics of a rendered and timed frame. Deterministic: the counters are
// exact and the cost model is a pure function of them.
Measurement measure_frame(const driver::FrameResult& frame);
// Adds quality.<name> for each of `quality` (keys as driver::FrameQuality::metrics).
void add_quality_metrics(Measurement& measurement, const std::map<std::string, double>& quality);

}  // namespace skinsim::budget
