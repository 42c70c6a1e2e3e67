// Where one configuration's DRAM traffic comes from: per pass, split by cause.
#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkColorSeries.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkNew.h>
#include <vtkPlotBar.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <algorithm>
#include <set>

#include "reports/chart_canvas.h"
#include "reports/charts.h"
#include "reports/error.h"

namespace skinsim::reports {

ChartFiles write_dram_by_cause_chart(const results::ConfigResult& row, const std::string& path_stem,
                                     const ChartOptions& options) {
  const std::vector<results::PassCost> passes = merged_passes(row);
  std::set<std::string> cause_set;
  for (const results::PassCost& p : passes) {
    for (const auto& [cause, bytes] : p.dram_bytes_by_cause) cause_set.insert(cause);
  }
  if (cause_set.empty()) {
    throw ReportError("DRAM chart " + path_stem + ": configuration '" + row.id +
                      "' has no dram_bytes_by_cause in any pass");
  }
  const std::vector<std::string> causes(cause_set.begin(), cause_set.end());
  constexpr double kBytesPerMB = 1e6;

  vtkNew<vtkTable> data;
  std::vector<double> position;
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < passes.size(); ++i) {
    position.push_back(static_cast<double>(i));
    labels.push_back(passes[i].name);
  }
  data->AddColumn(make_column("position", position));
  double y_hi = 0.0;
  std::vector<double> totals(passes.size(), 0.0);
  for (const std::string& cause : causes) {
    std::vector<double> mb(passes.size(), 0.0);
    for (std::size_t i = 0; i < passes.size(); ++i) {
      auto it = passes[i].dram_bytes_by_cause.find(cause);
      if (it != passes[i].dram_bytes_by_cause.end()) mb[i] = it->second / kBytesPerMB;
      totals[i] += mb[i];
      y_hi = std::max(y_hi, totals[i]);
    }
    data->AddColumn(make_column(cause, mb));
  }

  auto view = make_chart_view(options);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  style_chart(chart, "DRAM traffic per pass by cause: " + (row.label.empty() ? row.id : row.label),
              options);
  auto* bars = vtkPlotBar::SafeDownCast(chart->AddPlot(vtkChart::BAR));
  bars->SetInputData(data, "position", causes[0]);
  for (std::size_t k = 1; k < causes.size(); ++k) {
    bars->SetInputArray(static_cast<int>(k + 1), causes[k]);  // extra y arrays stack
  }
  vtkNew<vtkColorSeries> colours;
  colours->ClearColors();
  vtkNew<vtkStringArray> legend;
  for (std::size_t k = 0; k < causes.size(); ++k) {
    const Rgb c = palette_colour(k);
    colours->AddColor(vtkColor3ub(c[0], c[1], c[2]));
    legend->InsertNextValue(causes[k]);
  }
  bars->SetColorSeries(colours);
  bars->SetLabels(legend);
  bars->SetWidth(0.6f);

  vtkAxis* pass_axis = chart->GetAxis(vtkAxis::BOTTOM);
  style_axis(pass_axis, "pass", options);
  pass_axis->SetBehavior(vtkAxis::FIXED);
  pass_axis->SetRange(-0.6, static_cast<double>(passes.size()) - 0.4);
  set_ticks(pass_axis, position, labels);
  pass_axis->SetGridVisible(false);
  vtkAxis* value_axis = chart->GetAxis(vtkAxis::LEFT);
  style_axis(value_axis, "DRAM traffic per frame (MB, 10^6 bytes)", options);
  value_axis->SetBehavior(vtkAxis::FIXED);
  value_axis->SetRange(0.0, y_hi > 0.0 ? y_hi * 1.1 : 1.0);

  place_legend_outside(chart, options);
  return save_chart(view, path_stem, options);
}

}  // namespace skinsim::reports
