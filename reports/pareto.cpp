#include "reports/pareto.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace skinsim::reports {

namespace {

// Quality as "larger is better", so one comparison serves both directions.
double goodness(const results::ConfigResult& r, const std::string& metric, bool higher_is_better) {
  const double q = r.quality.at(metric);
  return higher_is_better ? q : -q;
}

bool dominates(const results::ConfigResult& a, const results::ConfigResult& b,
               const std::string& metric, bool higher_is_better,
               double results::ConfigResult::*cost) {
  const double ga = goodness(a, metric, higher_is_better);
  const double gb = goodness(b, metric, higher_is_better);
  const bool no_worse = a.*cost <= b.*cost && ga >= gb;
  const bool better = a.*cost < b.*cost || ga > gb;
  return no_worse && better;
}

// Maps v from [lo, hi] to [0, 1]; a zero-width range maps everything to 0.
double normalise(double v, double lo, double hi) {
  return hi > lo ? (v - lo) / (hi - lo) : 0.0;
}

}  // namespace

std::vector<std::size_t> pareto_front(const std::vector<results::ConfigResult>& rows,
                                      const std::string& metric, bool higher_is_better,
                                      double results::ConfigResult::*cost) {
  std::vector<std::size_t> with_metric;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].quality.count(metric)) with_metric.push_back(i);
  }
  std::vector<std::size_t> front;
  for (std::size_t i : with_metric) {
    const bool dominated = std::any_of(with_metric.begin(), with_metric.end(), [&](std::size_t j) {
      return dominates(rows[j], rows[i], metric, higher_is_better, cost);
    });
    if (!dominated) front.push_back(i);
  }
  std::stable_sort(front.begin(), front.end(),
                   [&](std::size_t a, std::size_t b) { return rows[a].*cost < rows[b].*cost; });
  return front;
}

std::optional<std::size_t> pareto_knee(const std::vector<results::ConfigResult>& rows,
                                       const std::string& metric, bool higher_is_better,
                                       double budget_ms) {
  std::vector<std::size_t> candidates;
  for (std::size_t i : pareto_front(rows, metric, higher_is_better)) {
    if (rows[i].frame_ms <= budget_ms) candidates.push_back(i);
  }
  if (candidates.empty()) return std::nullopt;
  double ms_lo = std::numeric_limits<double>::infinity(), ms_hi = -ms_lo;
  double g_lo = ms_lo, g_hi = -ms_lo;
  for (std::size_t i : candidates) {
    ms_lo = std::min(ms_lo, rows[i].frame_ms);
    ms_hi = std::max(ms_hi, rows[i].frame_ms);
    g_lo = std::min(g_lo, goodness(rows[i], metric, higher_is_better));
    g_hi = std::max(g_hi, goodness(rows[i], metric, higher_is_better));
  }
  std::size_t best = candidates.front();
  double best_distance = std::numeric_limits<double>::infinity();
  // A tie (e.g. a two-point front: (0,1) and (1,0)) goes to the better quality: both fit the
  // budget, and the time the cheaper one saves is time the budget did not ask to save.
  constexpr double kTie = 1e-9;
  for (std::size_t i : candidates) {
    const double time_cost = normalise(rows[i].frame_ms, ms_lo, ms_hi);
    const double quality_loss =
        1.0 - normalise(goodness(rows[i], metric, higher_is_better), g_lo, g_hi);
    const double distance = std::hypot(time_cost, g_hi > g_lo ? quality_loss : 0.0);
    const bool tie_but_better = std::abs(distance - best_distance) <= kTie &&
                                goodness(rows[i], metric, higher_is_better) >
                                    goodness(rows[best], metric, higher_is_better);
    if (distance < best_distance - kTie || tie_but_better) {
      best_distance = distance;
      best = i;
    }
  }
  return best;
}

std::string knee_rule_text() {
  return "The recommendation is the knee of the Pareto front within the frame budget: of the "
         "configurations that fit the budget and that no other configuration beats on both "
         "frame time and quality, the one nearest the ideal point (the cheapest frame time and "
         "the best quality among them), with both axes scaled to 0..1 over those "
         "configurations so that neither unit dominates; of equally near ones, the better "
         "quality. Past this point, extra milliseconds "
         "buy proportionally less quality; before it, a little more time buys a lot.";
}

}  // namespace skinsim::reports
