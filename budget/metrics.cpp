#include "budget/metrics.h"

#include <algorithm>

#include "gpu_model/timing.h"

namespace skinsim::budget {

namespace {

struct Totals {
  double fragments_shaded = 0.0;
  double fragments_depth_tested = 0.0;
  double triangles_in = 0.0;
  double texture_samples = 0.0;
  double cache_line_accesses = 0.0;
  double cache_misses = 0.0;
  double alu_ops = 0.0;

  void add(const sim::PassCounters& p) {
    fragments_shaded += static_cast<double>(p.fragments_shaded);
    fragments_depth_tested += static_cast<double>(p.fragments_depth_tested);
    triangles_in += static_cast<double>(p.triangles_in);
    texture_samples += static_cast<double>(p.texture.samples());
    cache_line_accesses += static_cast<double>(p.texture.cache_line_accesses);
    cache_misses += static_cast<double>(p.texture.cache_misses);
    // ALU instructions executed by the pass's shaders: fragment programs per shaded
    // fragment, vertex programs per shaded vertex (op counts from the shaders' own code).
    for (const sim::DrawCounters& d : p.draws) {
      alu_ops += static_cast<double>(d.fragments_shaded) * d.fragment_profile.alu_ops() +
                 static_cast<double>(d.vertices_shaded) * d.vertex_profile.alu_ops();
    }
  }
  double miss_rate() const {
    return cache_line_accesses > 0.0 ? cache_misses / cache_line_accesses : 0.0;
  }
  void write(MetricValues& out, const std::string& scope, double ms, double dram_bytes,
             double energy_mj) const {
    out[scope + ".ms"] = ms;
    out[scope + ".dram_bytes"] = dram_bytes;
    out[scope + ".energy_mj"] = energy_mj;
    out[scope + ".fragments_shaded"] = fragments_shaded;
    out[scope + ".texture_miss_rate"] = miss_rate();
    out[scope + ".alu_ops"] = alu_ops;
    out[scope + ".texture_samples"] = texture_samples;
    out[scope + ".fragments_depth_tested"] = fragments_depth_tested;
    out[scope + ".triangles_in"] = triangles_in;
  }
};

}  // namespace

const std::vector<std::string>& counter_metric_kinds() {
  static const std::vector<std::string> kinds = {
      "ms",       "dram_bytes",      "fragments_shaded",       "texture_miss_rate",
      "alu_ops",  "texture_samples", "fragments_depth_tested", "triangles_in",
      "energy_mj"};
  return kinds;
}

const std::vector<std::string>& quality_metric_names() {
  static const std::vector<std::string> names = {"psnr_skin",  "ssim_skin",  "flip_skin",
                                                 "psnr_frame", "ssim_frame", "flip_frame"};
  return names;
}

const std::vector<std::string>& sequence_metric_stats() {
  static const std::vector<std::string> stats = {"p50", "p95", "p99", "max", "mean"};
  return stats;
}

std::string metric_scope(const std::string& metric) {
  const std::size_t dot = metric.rfind('.');
  return dot == std::string::npos ? std::string() : metric.substr(0, dot);
}

std::string metric_kind(const std::string& metric) {
  const std::size_t dot = metric.rfind('.');
  return dot == std::string::npos ? metric : metric.substr(dot + 1);
}

bool is_quality_metric(const std::string& metric) {
  return metric_scope(metric) == "quality";
}

bool is_sequence_metric(const std::string& metric) {
  return metric_scope(metric) == "frame_ms";
}

bool is_known_metric_form(const std::string& metric) {
  const std::string scope = metric_scope(metric);
  const std::string kind = metric_kind(metric);
  if (scope.empty()) return false;
  if (scope == "frame_ms") {
    const auto& s = sequence_metric_stats();
    return std::find(s.begin(), s.end(), kind) != s.end();
  }
  if (scope == "quality") {
    const auto& q = quality_metric_names();
    return std::find(q.begin(), q.end(), kind) != q.end();
  }
  const auto& k = counter_metric_kinds();
  return std::find(k.begin(), k.end(), kind) != k.end();
}

Measurement measure_frame(const driver::FrameResult& frame) {
  Measurement m;
  const gpu_model::FrameTiming& timing = frame.timing;
  Totals frame_totals;
  for (std::size_t i = 0; i < frame.output.passes.size(); ++i) {
    const sim::PassCounters& counters = frame.output.passes[i];
    const gpu_model::PassTiming& t = timing.passes.at(i);
    // A pass's ms is its exposed share of the frame (render end minus the previous render
    // end, docs/cost-model.md), so the passes' ms add up to the pipeline time.
    const double ms = timing.schedule.at(i).exposed_ms;
    Totals pass;
    pass.add(counters);
    frame_totals.add(counters);
    pass.write(m.metrics, counters.name, ms, t.dram.total(), timing.energy.passes.at(i).mj.total());
    m.passes.push_back(counters.name);
    PassFacts facts;
    facts.bottleneck = gpu_model::unit_name(t.bottleneck);
    facts.bottleneck_share = t.utilisation[static_cast<int>(t.bottleneck)];
    facts.share_of_frame = timing.frame_ms > 0.0 ? ms / timing.frame_ms : 0.0;
    m.pass_facts[counters.name] = facts;
  }
  frame_totals.write(m.metrics, "frame", timing.frame_ms, timing.dram_bytes,
                     timing.energy.mj.total());
  return m;
}

void add_quality_metrics(Measurement& measurement, const std::map<std::string, double>& quality) {
  for (const auto& [name, value] : quality) measurement.metrics["quality." + name] = value;
}

}  // namespace skinsim::budget
