#include "reports/chart_canvas.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContext2D.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkPointData.h>
#include <vtkPoints2D.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkTransform2D.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <vector>

#include "image/error.h"
#include "image/image.h"
#include "io/atomic_file.h"
#include "reports/chart_svg.h"
#include "reports/display_check.h"
#include "reports/error.h"

namespace skinsim::reports {

namespace fs = std::filesystem;

vtkSmartPointer<vtkContextView> make_chart_view(const ChartOptions& options) {
  void* display = require_chart_display();  // before any VTK window exists: see display_check.h
  if (options.width < 200 || options.height < 150) {
    throw ReportError("chart size " + std::to_string(options.width) + "x" +
                      std::to_string(options.height) + " is too small (minimum 200x150)");
  }
  auto view = vtkSmartPointer<vtkContextView>::New();
  view->GetRenderWindow()->SetDisplayId(display);
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetSize(options.width, options.height);
  view->GetRenderWindow()->SetMultiSamples(0);  // GL2PS and PNG readback agree without MSAA
  return view;
}

void style_chart(vtkChart* chart, const std::string& title, const ChartOptions& options) {
  chart->SetTitle(title);
  chart->GetTitleProperties()->SetFontSize(options.title_font_size);
  chart->GetTitleProperties()->SetBold(true);
  chart->GetTitleProperties()->SetColor(0.1, 0.1, 0.1);
}

void style_axis(vtkAxis* axis, const std::string& title, const ChartOptions& options) {
  axis->SetTitle(title);
  axis->GetTitleProperties()->SetFontSize(options.axis_title_font_size);
  axis->GetTitleProperties()->SetBold(false);
  axis->GetTitleProperties()->SetColor(0.1, 0.1, 0.1);
  axis->GetLabelProperties()->SetFontSize(options.label_font_size);
  axis->GetLabelProperties()->SetColor(0.15, 0.15, 0.15);
  axis->GetGridPen()->SetColor(225, 225, 225);
}

vtkSmartPointer<vtkDoubleArray> make_column(const std::string& name,
                                            const std::vector<double>& values) {
  auto column = vtkSmartPointer<vtkDoubleArray>::New();
  column->SetName(name.c_str());
  column->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i) {
    column->SetValue(static_cast<vtkIdType>(i), values[i]);
  }
  return column;
}

void set_ticks(vtkAxis* axis, const std::vector<double>& positions,
               const std::vector<std::string>& labels) {
  vtkNew<vtkDoubleArray> where;
  vtkNew<vtkStringArray> text;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    where->InsertNextValue(positions[i]);
    text->InsertNextValue(labels[i]);
  }
  axis->SetCustomTickPositions(where, text);
}

void add_vertical_line(vtkChartXY* chart, double at, double y_lo, double y_hi,
                       const std::string& legend, const Rgb& colour) {
  vtkNew<vtkTable> table;
  table->AddColumn(make_column("x", {at, at}));
  table->AddColumn(make_column(legend, {y_lo, y_hi}));
  vtkPlot* line = chart->AddPlot(vtkChart::LINE);
  line->SetInputData(table, 0, 1);
  line->SetColor(colour[0], colour[1], colour[2], 255);
  line->SetWidth(3.0);
  line->GetPen()->SetLineType(vtkPen::DASH_LINE);
}

vtkPlotPoints* add_series(vtkChartXY* chart, const std::string& name, const std::vector<double>& x,
                          const std::vector<double>& y, const Rgb& colour, int line_type) {
  if (x.size() < 2) line_type = vtkPen::NO_PEN;
  vtkNew<vtkTable> table;
  table->AddColumn(make_column("x", x));
  table->AddColumn(make_column(name, y));
  auto* plot = vtkPlotPoints::SafeDownCast(
      chart->AddPlot(line_type == vtkPen::NO_PEN ? vtkChart::POINTS : vtkChart::LINE));
  plot->SetInputData(table, 0, 1);
  plot->SetColor(colour[0], colour[1], colour[2], 255);
  plot->SetMarkerStyle(vtkPlotPoints::CIRCLE);
  plot->SetMarkerSize(10.0);
  plot->SetWidth(2.5);
  plot->GetPen()->SetLineType(line_type);
  return plot;
}

namespace {

struct Box {
  float x0, y0, x1, y1;  // scene pixels
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// Invisible points that each write their text beside them, placed in scene pixels when the
// chart paints: right of the point (left of it where that would leave the plot area), moved up
// or down a text line at a time, nearest first, until it overlaps neither a label placed before
// it nor a marker of the points to avoid, with a thin line back to its point when moved. A plot,
// not a scene item, so the chart maps the points (log axes included) as it maps the data's.
class PointLabels : public vtkPlotPoints {
 public:
  static PointLabels* New();
  std::vector<std::string> texts;  // one per point, then "" for each point to avoid
  int font_size = 19;
  vtkChart* chart = nullptr;  // owns this plot

  bool Paint(vtkContext2D* painter) override {
    if (this->Points == nullptr ||
        this->Points->GetNumberOfPoints() != static_cast<vtkIdType>(texts.size())) {
      return false;
    }
    std::vector<float> at(2 * texts.size());
    for (std::size_t i = 0; i < texts.size(); ++i) {
      double p[2];
      this->Points->GetPoint(static_cast<vtkIdType>(i), p);
      at[2 * i] = static_cast<float>(p[0]);
      at[2 * i + 1] = static_cast<float>(p[1]);
    }
    painter->GetTransform()->TransformPoints(at.data(), at.data(), static_cast<int>(texts.size()));
    painter->PushMatrix();
    vtkNew<vtkTransform2D> scene;  // identity: draw in scene pixels
    painter->SetTransform(scene);
    vtkTextProperty* prop = painter->GetTextProp();
    prop->SetFontSize(font_size);
    prop->SetColor(0.1, 0.1, 0.1);
    prop->SetJustificationToLeft();
    prop->SetVerticalJustificationToBottom();
    painter->GetPen()->SetLineType(vtkPen::SOLID_LINE);
    painter->GetPen()->SetColorF(0.3, 0.3, 0.3);
    painter->GetPen()->SetWidth(1.0f);
    const float gap = 0.5f * static_cast<float>(font_size);  // clear of the point's marker
    const int* lo = chart->GetPoint1();
    const int* hi = chart->GetPoint2();
    std::vector<Box> placed;  // the data's markers (10 px), then the labels
    for (std::size_t i = 0; i < texts.size(); ++i) {
      if (texts[i].empty()) {
        placed.push_back({at[2 * i] - 6, at[2 * i + 1] - 6, at[2 * i] + 6, at[2 * i + 1] + 6});
      }
    }
    for (std::size_t i = 0; i < texts.size(); ++i) {
      if (texts[i].empty()) continue;
      float bounds[4];
      painter->ComputeStringBounds(texts[i], bounds);
      const float w = bounds[2], h = bounds[3];
      const float x = at[2 * i], y = at[2 * i + 1];
      const float left = x + gap + w > static_cast<float>(hi[0]) ? x - gap - w : x + gap;
      Box box{left, y - h / 2, left + w, y + h / 2};
      // Up and down as far as the plot area reaches, at most; a label that finds no room
      // there stays at the last place tried (clamped into the plot area below).
      const int steps = 2 * static_cast<int>((hi[1] - lo[1]) / std::max(h, 1.0f)) + 1;
      for (int step = 1; step <= steps; ++step) {
        if (std::none_of(placed.begin(), placed.end(),
                         [&](const Box& o) { return o.overlaps(box); })) {
          break;
        }
        const float shift = static_cast<float>((step + 1) / 2) * h * (step % 2 ? 1.0f : -1.0f);
        box = {left, y - h / 2 + shift, left + w, y + h / 2 + shift};
      }
      box.y0 = std::clamp(box.y0, static_cast<float>(lo[1]), static_cast<float>(hi[1]) - h);
      box.y1 = box.y0 + h;
      placed.push_back(box);
      if (box.y0 > y || box.y1 < y) {
        painter->DrawLine(x, y, box.x0 < x ? box.x1 : box.x0, box.y0 > y ? box.y0 : box.y1);
      }
      painter->DrawString(box.x0, box.y0, texts[i]);
    }
    painter->PopMatrix();
    return true;
  }

  // Last: it takes no semicolon, which clang-format would read as continuing onto the next line.
  vtkTypeMacro(PointLabels, vtkPlotPoints)
};
vtkStandardNewMacro(PointLabels);

}  // namespace

void add_point_labels(vtkChartXY* chart, const std::vector<PointLabel>& labels,
                      const std::vector<std::array<double, 2>>& avoid,
                      const ChartOptions& options) {
  if (labels.empty()) return;
  vtkNew<PointLabels> plot;
  std::vector<double> x, y;
  for (const PointLabel& l : labels) {
    x.push_back(l.x);
    y.push_back(l.y);
    plot->texts.push_back(l.text);
  }
  for (const auto& [px, py] : avoid) {
    x.push_back(px);
    y.push_back(py);
    plot->texts.emplace_back();
  }
  plot->font_size = options.label_font_size;
  plot->chart = chart;
  vtkNew<vtkTable> table;
  table->AddColumn(make_column("x", x));
  table->AddColumn(make_column("labels", y));
  plot->SetInputData(table, 0, 1);
  plot->SetMarkerStyle(vtkPlotPoints::NONE);
  plot->SetLegendVisibility(false);
  chart->AddPlot(plot);
}

void add_range_bar(vtkChartXY* chart, const std::string& legend, double x_lo, double x_hi, double y,
                   bool in_legend) {
  vtkPlotPoints* bar =
      add_series(chart, legend, {x_lo, x_hi}, {y, y}, {150, 150, 150}, vtkPen::SOLID_LINE);
  bar->SetColor(150, 150, 150, 140);  // light: the ranges overlap and must not hide the points
  bar->SetMarkerStyle(vtkPlotPoints::PLUS);
  bar->SetMarkerSize(8.0);
  bar->SetWidth(1.0);
  bar->SetLegendVisibility(in_legend);
}

AxisRange cost_axis_range(double lo, double hi, double pad) {
  if (hi > 10.0 * lo && lo > 0.0) return {lo / 1.15, hi * 1.15, true};
  AxisRange r{std::max(0.0, lo - 0.06 * (hi - lo) - pad), hi + 0.06 * (hi - lo) + pad, false};
  if (r.hi <= r.lo) r.hi = r.lo + 1.0;  // all values equal, and no pad: VTK needs a span
  return r;
}

AxisRange quality_axis_range(double lo, double hi, bool higher_is_better) {
  const double min_span = 0.10 * std::max(std::abs(lo), std::abs(hi));
  const double span = std::max(1.16 * (hi - lo), std::max(min_span, 1e-6));
  const double mid = (lo + hi) / 2.0;
  AxisRange r{mid - span / 2.0, mid + span / 2.0, false};
  if (!higher_is_better && r.lo < 0.0) {  // an error is never negative
    r.hi -= r.lo;
    r.lo = 0.0;
  }
  return r;
}

void place_legend_outside(vtkChartXY* chart, const ChartOptions& options) {
  chart->SetShowLegend(true);
  vtkChartLegend* legend = chart->GetLegend();
  legend->SetInline(false);
  legend->SetLabelSize(options.legend_font_size);
  legend->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  legend->SetVerticalAlignment(vtkChartLegend::TOP);
}

namespace {

void write_png(vtkRenderWindow* window, const std::string& path) {
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  int size[3] = {0, 0, 0};
  image->GetDimensions(size);
  auto* pixels = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (pixels == nullptr || pixels->GetNumberOfComponents() != 3 || size[0] <= 0 || size[1] <= 0 ||
      pixels->GetNumberOfTuples() != static_cast<vtkIdType>(size[0]) * size[1]) {
    throw ReportError("cannot write chart " + path + ": the window's pixels could not be read");
  }
  // OpenGL's rows run bottom-up, a PNG's top-down. Encoded by skinsim's PNG writer
  // (libdeflate, quality/png_encode.h), faster than VTK's libpng writer on the one core the
  // charts draw on (docs/performance.md), and written checked and atomically.
  const std::size_t row = static_cast<std::size_t>(size[0]) * 3;
  std::vector<std::uint8_t> top_down(row * static_cast<std::size_t>(size[1]));
  const unsigned char* bottom_up = pixels->GetPointer(0);
  for (int y = 0; y < size[1]; ++y) {
    std::memcpy(&top_down[row * static_cast<std::size_t>(size[1] - 1 - y)], bottom_up + row * y,
                row);
  }
  try {
    image::write_png_u8(path, size[0], size[1], 3, top_down);
  } catch (const image::ImageError& e) {
    throw ReportError("cannot write chart " + path + ": " + e.what());
  }
}

}  // namespace

ChartFiles save_chart(vtkContextView* view, const std::string& path_stem,
                      const ChartOptions& options) {
  const fs::path dir = fs::path(path_stem).parent_path();
  std::error_code ec;
  if (!dir.empty()) fs::create_directories(dir, ec);
  if (ec) throw ReportError("cannot create directory " + dir.string() + ": " + ec.message());
  vtkRenderWindow* window = view->GetRenderWindow();
  window->Render();
  ChartFiles files;
  files.png = path_stem + ".png";
  write_png(window, files.png);
  if (options.write_svg) {
    files.svg = path_stem + ".svg";
    // GL2PS's vector pass leaves the window so: every chart saves last.
    write_chart_svg(window, files.svg);
  }
  return files;
}

}  // namespace skinsim::reports
