// Energy per frame vs quality: what a configuration costs in battery, beside the trade-off
// chart's milliseconds.
#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlotPoints.h>

#include <algorithm>
#include <cmath>

#include "reports/chart_canvas.h"
#include "reports/charts.h"
#include "reports/error.h"
#include "reports/pareto.h"
#include "reports/recommendation.h"

namespace skinsim::reports {

ChartFiles write_energy_chart(const results::SweepTable& table, const QualityAxis& quality,
                              const std::string& path_stem, const ChartOptions& options) {
  std::vector<const results::ConfigResult*> rows;
  for (const results::ConfigResult& r : table.rows) {
    if (r.quality.count(quality.metric)) rows.push_back(&r);
  }
  if (rows.empty()) {
    throw ReportError("energy chart " + path_stem + ": no configuration has quality metric '" +
                      quality.metric + "'");
  }
  const std::vector<std::string> groups = groups_in_order(table);

  auto view = make_chart_view(options);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  style_chart(chart, "Energy per frame vs " + quality.metric + ": one colour per device group",
              options);

  double y_lo = INFINITY, y_hi = -INFINITY, x_lo = INFINITY, x_hi = -INFINITY;
  for (const results::ConfigResult* r : rows) {
    y_lo = std::min(y_lo, r->quality.at(quality.metric));
    y_hi = std::max(y_hi, r->quality.at(quality.metric));
    x_lo = std::min(x_lo, r->energy_mj_low);
    x_hi = std::max(x_hi, r->energy_mj_high);
  }
  const AxisRange x_range = cost_axis_range(x_lo, x_hi, 0.02 * x_hi);
  const AxisRange y_range = quality_axis_range(y_lo, y_hi, quality.higher_is_better);

  // Energy ranges over the profile's energy figures, as horizontal error bars.
  bool first = true;
  for (const results::ConfigResult* r : rows) {
    const double y = r->quality.at(quality.metric);
    add_range_bar(chart, "mJ range", r->energy_mj_low, r->energy_mj_high, y, first);
    first = false;
  }

  // Per group its configurations, and the Pareto front of energy vs quality among them dotted
  // in the same colour (unnamed in the legend: the caption says what it is).
  std::size_t colour = 0;
  for (const std::string& group : groups) {
    std::vector<results::ConfigResult> members;
    for (const results::ConfigResult* r : rows) {
      if (r->group == group) members.push_back(*r);
    }
    if (members.empty()) continue;
    std::vector<double> x, y;
    for (const results::ConfigResult& r : members) {
      x.push_back(r.energy_mj);
      y.push_back(r.quality.at(quality.metric));
    }
    const Rgb rgb = palette_colour(colour++);
    add_series(chart, group.empty() ? "configurations" : group, x, y, rgb, vtkPen::NO_PEN);
    std::vector<double> front_x, front_y;
    for (std::size_t i : pareto_front(members, quality.metric, quality.higher_is_better,
                                      &results::ConfigResult::energy_mj)) {
      front_x.push_back(members[i].energy_mj);
      front_y.push_back(members[i].quality.at(quality.metric));
    }
    vtkPlotPoints* front =
        add_series(chart, group + ": energy Pareto front", front_x, front_y, rgb, vtkPen::DOT_LINE);
    front->SetMarkerStyle(vtkPlotPoints::NONE);
    front->SetLegendVisibility(false);
  }

  // Over the frame budget: however little energy, not a candidate.
  std::vector<double> over_x, over_y;
  for (const results::ConfigResult* r : rows) {
    if (r->frame_ms <= table.budget_ms) continue;
    over_x.push_back(r->energy_mj);
    over_y.push_back(r->quality.at(quality.metric));
  }
  if (!over_x.empty()) {
    vtkPlotPoints* cross =
        add_series(chart, "over the frame budget " + budget_label(table.budget_ms), over_x, over_y,
                   {20, 20, 20}, vtkPen::NO_PEN);
    cross->SetMarkerStyle(vtkPlotPoints::CROSS);
    cross->SetMarkerSize(18.0);
  }

  // The report's recommendations, one per group; their rule needs a lower-is-better metric.
  if (!quality.higher_is_better) {
    first = true;
    for (const Recommendation& rec : recommend(table, quality.metric)) {
      if (!rec.chosen) continue;
      const results::ConfigResult& r = table.rows[*rec.chosen];
      vtkPlotPoints* mark = add_series(chart, "recommended", {r.energy_mj},
                                       {r.quality.at(quality.metric)}, {200, 0, 0}, vtkPen::NO_PEN);
      mark->SetMarkerStyle(vtkPlotPoints::DIAMOND);
      mark->SetMarkerSize(26.0);
      mark->SetLegendVisibility(first);
      first = false;
    }
  }

  vtkAxis* x_axis = chart->GetAxis(vtkAxis::BOTTOM);
  style_axis(
      x_axis,
      x_range.log ? "dynamic energy per frame (mJ, log scale)" : "dynamic energy per frame (mJ)",
      options);
  x_axis->SetBehavior(vtkAxis::FIXED);
  x_axis->SetLogScale(x_range.log);
  x_axis->SetRange(x_range.lo, x_range.hi);
  vtkAxis* y_axis = chart->GetAxis(vtkAxis::LEFT);
  style_axis(y_axis, quality.label, options);
  y_axis->SetBehavior(vtkAxis::FIXED);
  y_axis->SetRange(y_range.lo, y_range.hi);

  place_legend_outside(chart, options);
  return save_chart(view, path_stem, options);
}

}  // namespace skinsim::reports
