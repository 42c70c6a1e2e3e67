#include "budget/explain.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "budget/value_format.h"

namespace skinsim::budget {

namespace {

std::optional<double> lookup(const MetricValues& values, const std::string& metric) {
  const auto it = values.find(metric);
  if (it == values.end()) return std::nullopt;
  return it->second;
}

// "ALU ops 1.2e6 -> 1.8e6 (+50.0%)" when the baseline has the metric, else "ALU ops 1.8e6".
std::string evidence(const std::string& label, const std::string& metric, const Measurement& now,
                     const BaselineEntry* baseline) {
  const std::optional<double> value = lookup(now.metrics, metric);
  if (!value) return {};
  const std::optional<double> before = baseline ? lookup(baseline->metrics, metric) : std::nullopt;
  if (!before) return fmt::format("{} {}", label, format_value(metric, *value));
  if (*before == *value)
    return fmt::format("{} {}, unchanged", label, format_value(metric, *value));
  return fmt::format("{} {} -> {} ({})", label, format_value(metric, *before),
                     format_value(metric, *value), format_change(*before, *value));
}

// Why a pass costs what it costs: the unit that bounds it in the cost model, and what grows
// that unit's work.
std::string pass_cause(const std::string& kind, const std::string& pass, const Measurement& now,
                       const BaselineEntry* baseline) {
  const auto facts = now.pass_facts.find(pass);
  if (facts == now.pass_facts.end()) return {};
  const PassFacts& f = facts->second;
  const std::string head = fmt::format("the {} pass is {}-bound ({:.0f}% busy)", pass, f.bottleneck,
                                       f.bottleneck_share * 100.0);
  const std::string p = pass + ".";
  // Traffic is not time: say where the bytes go, and whether they also set the pass's time.
  if (kind == "dram_bytes") {
    return fmt::format(
        "the {} pass's {}{}", pass, evidence("DRAM traffic", p + "dram_bytes", now, baseline),
        f.bottleneck == "bandwidth" ? " and is bandwidth-bound, so its time grows with it" : "");
  }
  if (f.bottleneck == "alu") {
    return fmt::format(
        "{}, so its time follows its shaders' ALU work: the fragment shader's op count or the "
        "fragments it shades grew ({}; {})",
        head, evidence("ALU ops", p + "alu_ops", now, baseline),
        evidence("fragments shaded", p + "fragments_shaded", now, baseline));
  }
  if (f.bottleneck == "texture") {
    return fmt::format(
        "{}, so its time follows texture fetches: more samples or worse cache locality ({}; {})",
        head, evidence("samples", p + "texture_samples", now, baseline),
        evidence("miss rate", p + "texture_miss_rate", now, baseline));
  }
  if (f.bottleneck == "isp") {
    return fmt::format(
        "{}, so its time follows hidden-surface removal: more overdraw or coverage ({})", head,
        evidence("fragments depth-tested", p + "fragments_depth_tested", now, baseline));
  }
  if (f.bottleneck == "bandwidth") {
    return fmt::format("{}, so its time follows its DRAM traffic ({})", head,
                       evidence("DRAM", p + "dram_bytes", now, baseline));
  }
  if (f.bottleneck == "tiler") {
    return fmt::format(
        "{}, so its time follows vertex shading and binning: more triangles or vertex work "
        "({})",
        head, evidence("triangles", p + "triangles_in", now, baseline));
  }
  return head + ", so fixed per-pass costs dominate it";
}

// The pass whose `kind` grew the most since the baseline (`delta` set), or, when none grew or
// there is no baseline, the pass with the largest value (`delta` NaN).
std::string culprit_pass(const std::string& kind, const Measurement& now,
                         const BaselineEntry* baseline, double* delta) {
  std::string grown;
  std::string largest;
  double most_growth = 0.0;
  double largest_value = -INFINITY;
  for (const std::string& pass : now.passes) {
    const std::string metric = pass + "." + kind;
    const std::optional<double> value = lookup(now.metrics, metric);
    if (!value) continue;
    if (*value > largest_value) {
      largest_value = *value;
      largest = pass;
    }
    const std::optional<double> before =
        baseline ? lookup(baseline->metrics, metric) : std::nullopt;
    if (before && *value - *before > most_growth) {
      most_growth = *value - *before;
      grown = pass;
    }
  }
  *delta = grown.empty() ? NAN : most_growth;
  return grown.empty() ? largest : grown;
}

std::string what_moved(const LimitResult& r, const BaselineEntry* baseline) {
  const std::string& metric = r.limit.metric;
  const std::string limit =
      fmt::format("{} {}", comparison_text(r.limit.comparison), format_value(metric, r.bound));
  if (r.baseline) {
    const double b = *r.baseline;
    const std::string tolerance = fmt::format("tolerance {}: limit \"{}\" = {}",
                                              r.limit.tolerance_text(), r.limit.text, limit);
    if (r.measured == b) {
      return fmt::format("{} is unchanged at {} ({})", metric, format_value(metric, b), tolerance);
    }
    return fmt::format("{} {} from {} to {} ({}, {})", metric, r.measured > b ? "rose" : "fell",
                       format_value(metric, b), format_value(metric, r.measured),
                       format_change(b, r.measured), tolerance);
  }
  std::string text =
      fmt::format("{} is {}, {} its limit {} by {}", metric, format_value(metric, r.measured),
                  r.limit.comparison == Comparison::kAtMost ? "above" : "below", limit,
                  format_value(metric, std::fabs(r.margin)));
  if (const auto before = baseline ? lookup(baseline->metrics, metric) : std::nullopt) {
    text += fmt::format(" (baseline {}, {})", format_value(metric, *before),
                        format_change(*before, r.measured));
  }
  return text;
}

std::string frame_consequence(const Budget& budget, const Measurement& now) {
  const double frame_ms = lookup(now.metrics, "frame.ms").value_or(0.0);
  const double target_ms = 1000.0 / budget.target_fps;
  if (frame_ms > target_ms) {
    return fmt::format("the frame now takes {:.3f} ms ({:.1f} fps) and misses {:g} fps ({:.2f} ms)",
                       frame_ms, 1000.0 / frame_ms, budget.target_fps, target_ms);
  }
  return fmt::format("the frame takes {:.3f} ms, {:.2f} ms inside the {:.2f} ms of {:g} fps",
                     frame_ms, target_ms - frame_ms, target_ms, budget.target_fps);
}

}  // namespace

std::string explain_failure(const Budget& budget, const LimitResult& r, const Measurement& now,
                            const BaselineEntry* baseline) {
  const std::string scope = metric_scope(r.limit.metric);
  const std::string kind = metric_kind(r.limit.metric);
  std::string text = what_moved(r, baseline);
  // A cost below its lower limit is not a win to explain by what grew: the usual cause is a
  // pass, draw or fragments that no longer run.
  if (scope != "quality" && r.limit.comparison == Comparison::kAtLeast) {
    return text +
           "; the cost dropped unexpectedly: did work go missing? If the saving is intended, "
           "re-record the baseline (skinsim baseline FILE --update)";
  }
  if (scope == "quality") {
    return text +
           "; the frame differs more from the reference than the budget allows, so "
           "the technique's approximation error is now visible at this floor";
  }
  if (scope == "frame_ms") {
    return text + "; " + now.sequence_summary;
  }
  if (scope == "frame") {
    double delta = NAN;
    const std::string pass = culprit_pass(kind, now, baseline, &delta);
    if (!pass.empty()) {
      const std::string metric = pass + "." + kind;
      text += std::isnan(delta)
                  ? fmt::format("; the largest part is the {} pass ({})", pass,
                                format_value(metric, lookup(now.metrics, metric).value_or(0.0)))
                  : fmt::format("; most of the change is the {} pass ({})", pass,
                                format_delta(metric, delta));
      text += "; " + pass_cause(kind, pass, now, baseline);
    }
  } else {
    text += "; " + pass_cause(kind, scope, now, baseline);
  }
  if (kind == "ms") text += "; " + frame_consequence(budget, now);
  if (kind == "dram_bytes") {
    const double bytes = r.measured;
    text += fmt::format(
        "; at {:g} fps that is {:.2f} GB/s of DRAM traffic, which costs power "
        "and competes with the CPU",
        budget.target_fps, bytes * budget.target_fps / 1e9);
  }
  return text;
}

}  // namespace skinsim::budget
