// Frame time over a sequence, and its per-pass stack.
#include "reports/sequence_charts.h"

#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkColorSeries.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotStacked.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <algorithm>

#include "reports/chart_canvas.h"
#include "reports/error.h"

namespace skinsim::reports {

namespace {

void require_frames(const SequenceSeries& s, const std::string& path_stem) {
  if (s.time_s.empty()) throw ReportError("sequence chart " + path_stem + ": no frames");
}

// The budget as a dashed horizontal line over the sequence's time span.
void add_budget_line(vtkChartXY* chart, const SequenceSeries& s) {
  vtkNew<vtkTable> table;
  table->AddColumn(make_column("t", {s.time_s.front(), s.time_s.back()}));
  table->AddColumn(make_column("budget " + budget_label(s.budget_ms), {s.budget_ms, s.budget_ms}));
  vtkPlot* line = chart->AddPlot(vtkChart::LINE);
  line->SetInputData(table, 0, 1);
  line->SetColor(200, 0, 0, 255);
  line->SetWidth(3.0);
  line->GetPen()->SetLineType(vtkPen::DASH_LINE);
}

void style_axes(vtkChartXY* chart, const SequenceSeries& s, double y_hi, const std::string& y_title,
                const ChartOptions& options) {
  vtkAxis* x = chart->GetAxis(vtkAxis::BOTTOM);
  style_axis(x, "time in the sequence (s)", options);
  x->SetBehavior(vtkAxis::FIXED);
  x->SetRange(s.time_s.front(), std::max(s.time_s.back(), s.time_s.front() + 1e-3));
  vtkAxis* y = chart->GetAxis(vtkAxis::LEFT);
  style_axis(y, y_title, options);
  y->SetBehavior(vtkAxis::FIXED);
  y->SetRange(0.0, y_hi * 1.05);
}

}  // namespace

ChartFiles write_sequence_frame_chart(const SequenceSeries& s, const std::string& path_stem,
                                      const ChartOptions& options) {
  require_frames(s, path_stem);
  vtkNew<vtkTable> data;
  data->AddColumn(make_column("t", s.time_s));
  data->AddColumn(make_column("frame ms", s.frame_ms));
  data->AddColumn(make_column("range low", s.low_ms));
  data->AddColumn(make_column("range high", s.high_ms));

  auto view = make_chart_view(options);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  style_chart(chart, "Frame time over the sequence: " + s.title, options);
  const struct {
    int column;
    Rgb colour;
    float width;
  } lines[] = {
      {1, palette_colour(0), 4.0f}, {2, {150, 150, 150}, 1.5f}, {3, {150, 150, 150}, 1.5f}};
  for (const auto& l : lines) {
    vtkPlot* plot = chart->AddPlot(vtkChart::LINE);
    plot->SetInputData(data, 0, l.column);
    plot->SetColor(l.colour[0], l.colour[1], l.colour[2], 255);
    plot->SetWidth(l.width);
  }
  add_budget_line(chart, s);
  const double y_hi = std::max(s.budget_ms, *std::max_element(s.high_ms.begin(), s.high_ms.end()));
  style_axes(chart, s, y_hi, "modelled frame time (ms)", options);
  place_legend_outside(chart, options);
  return save_chart(view, path_stem, options);
}

ChartFiles write_sequence_pass_chart(const SequenceSeries& s, const std::string& path_stem,
                                     const ChartOptions& options) {
  require_frames(s, path_stem);
  if (s.pass_names.empty()) throw ReportError("sequence chart " + path_stem + ": no passes");
  vtkNew<vtkTable> data;
  data->AddColumn(make_column("t", s.time_s));
  for (std::size_t k = 0; k < s.pass_names.size(); ++k) {
    data->AddColumn(make_column(s.pass_names[k], s.pass_ms[k]));
  }

  auto view = make_chart_view(options);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  style_chart(chart, "Frame time by pass over the sequence: " + s.title, options);
  auto* stack = vtkPlotStacked::SafeDownCast(chart->AddPlot(vtkChart::STACKED));
  stack->SetInputData(data, "t", s.pass_names[0]);
  for (std::size_t k = 1; k < s.pass_names.size(); ++k) {
    stack->SetInputArray(static_cast<int>(k + 1), s.pass_names[k]);  // extra y arrays stack
  }
  vtkNew<vtkColorSeries> colours;
  colours->ClearColors();
  vtkNew<vtkStringArray> legend;
  for (const std::string& name : s.pass_names) {
    const Rgb c = pass_colour(name, s.pass_names);
    colours->AddColor(vtkColor3ub(c[0], c[1], c[2]));
    legend->InsertNextValue(name);
  }
  stack->SetColorSeries(colours);
  stack->SetLabels(legend);
  add_budget_line(chart, s);
  const double y_hi =
      std::max(s.budget_ms, *std::max_element(s.frame_ms.begin(), s.frame_ms.end()));
  // The legend lists only the stacked plot's series, so the budget line is named in the title.
  style_axes(chart, s, y_hi,
             "modelled frame time (ms); dashed red line: budget " + budget_label(s.budget_ms),
             options);
  place_legend_outside(chart, options);
  return save_chart(view, path_stem, options);
}

ChartFiles write_sequence_quality_chart(const SequenceSeries& s, const std::string& path_stem,
                                        const ChartOptions& options) {
  require_frames(s, path_stem);
  if (s.quality.size() != s.time_s.size() || s.temporal_error.size() + 1 != s.time_s.size()) {
    throw ReportError("sequence chart " + path_stem + ": no per-frame quality");
  }
  vtkNew<vtkTable> frames;
  frames->AddColumn(make_column("t", s.time_s));
  frames->AddColumn(make_column(s.quality_label + " vs the frame's reference", s.quality));
  vtkNew<vtkTable> steps;  // a step is drawn at the time of the frame it leads to
  steps->AddColumn(make_column("t", {s.time_s.begin() + 1, s.time_s.end()}));
  steps->AddColumn(
      make_column("temporal error (FLIP change vs the reference's)", s.temporal_error));

  auto view = make_chart_view(options);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  style_chart(chart, "Quality over the sequence: " + s.title, options);
  double y_hi = 1e-3;
  for (const auto& [table, colour] :
       {std::pair{frames.Get(), palette_colour(0)}, std::pair{steps.Get(), palette_colour(1)}}) {
    vtkPlot* plot = chart->AddPlot(vtkChart::LINE);
    plot->SetInputData(table, 0, 1);
    plot->SetColor(colour[0], colour[1], colour[2], 255);
    plot->SetWidth(4.0);
  }
  for (const std::vector<double>* v : {&s.quality, &s.temporal_error}) {
    if (!v->empty()) y_hi = std::max(y_hi, *std::max_element(v->begin(), v->end()));
  }
  style_axes(chart, s, y_hi, "FLIP (lower is better)", options);
  place_legend_outside(chart, options);
  return save_chart(view, path_stem, options);
}

}  // namespace skinsim::reports
