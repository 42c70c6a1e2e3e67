// Per-tile pictures of one pass over the frame: cost heat map and bottleneck map.
#include <fmt/format.h>
#include <vtkAxis.h>
#include <vtkChartHistogram2D.h>
#include <vtkColorLegend.h>
#include <vtkColorTransferFunction.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkTextProperty.h>

#include <algorithm>

#include "reports/chart_canvas.h"
#include "reports/charts.h"
#include "reports/error.h"
#include "reports/knob_order.h"

namespace skinsim::reports {

namespace {

// VTK 9.1's vtkColorLegend keeps its axis protected with no accessor, so its fonts and tick
// labels could not be set. A pointer to the inherited member, formed in a derived class, may
// be applied to any vtkColorLegend (C++ [expr.unary.op]: access is checked where the pointer
// is formed).
struct ColorLegendAxis : vtkColorLegend {
  static vtkAxis* of(vtkColorLegend* legend) { return (legend->*(&ColorLegendAxis::Axis)).Get(); }
};

// Image with one pixel per tile; image row j holds tile row tiles_y - 1 - j so that the top of
// the frame is at the top of the chart (VTK's y axis points up).
vtkSmartPointer<vtkImageData> tile_image(const results::TileHeatmap& h,
                                         const std::vector<double>& values) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(h.tiles_x, h.tiles_y, 1);
  image->SetOrigin(0.0, 0.0, 0.0);
  image->SetSpacing(1.0, 1.0, 1.0);
  image->AllocateScalars(VTK_DOUBLE, 1);
  auto* out = static_cast<double*>(image->GetScalarPointer());
  for (int ty = 0; ty < h.tiles_y; ++ty) {
    for (int tx = 0; tx < h.tiles_x; ++tx) {
      out[(h.tiles_y - 1 - ty) * h.tiles_x + tx] = values[ty * h.tiles_x + tx];
    }
  }
  return image;
}

void check_heatmap(const results::TileHeatmap& h, const std::string& what) {
  const std::size_t n = static_cast<std::size_t>(std::max(h.tiles_x, 0)) *
                        static_cast<std::size_t>(std::max(h.tiles_y, 0));
  if (n == 0 || h.ms.size() != n) {
    throw ReportError(what + ": heat map needs tiles_x * tiles_y ms values (" +
                      std::to_string(h.tiles_x) + " x " + std::to_string(h.tiles_y) + ", got " +
                      std::to_string(h.ms.size()) + ")");
  }
}

// Tick marks every `step` tiles at tile centres, labelled by tile index from the top/left.
// The histogram draws image pixel i over [i, i + 1).
void tile_ticks(vtkAxis* axis, int count, bool from_top) {
  const int step = std::max(1, count / 8);
  std::vector<double> at;
  std::vector<std::string> text;
  for (int i = 0; i < count; i += step) {
    at.push_back((from_top ? count - 1 - i : i) + 0.5);
    text.push_back(std::to_string(i));
  }
  set_ticks(axis, at, text);
}

vtkSmartPointer<vtkContextView> tile_chart(const results::TileHeatmap& h, vtkImageData* image,
                                           vtkColorTransferFunction* colours,
                                           const std::string& title, const std::string& legend,
                                           const ChartOptions& options, vtkChartHistogram2D** out) {
  auto view = make_chart_view(options);
  vtkNew<vtkChartHistogram2D> chart;
  view->GetScene()->AddItem(chart);
  chart->SetInputData(image);
  chart->SetTransferFunction(colours);
  style_chart(chart, title, options);
  const std::string px = std::to_string(h.tile_size);
  vtkAxis* x_axis = chart->GetAxis(vtkAxis::BOTTOM);
  style_axis(x_axis, "tile column (" + px + " px tiles, from the left)", options);
  x_axis->SetBehavior(vtkAxis::FIXED);  // exactly the image: no "nice" rounding of the range
  x_axis->SetRange(0.0, h.tiles_x);
  tile_ticks(x_axis, h.tiles_x, false);
  vtkAxis* y_axis = chart->GetAxis(vtkAxis::LEFT);
  style_axis(y_axis, "tile row (from the top)", options);
  y_axis->SetBehavior(vtkAxis::FIXED);
  y_axis->SetRange(0.0, h.tiles_y);
  tile_ticks(y_axis, h.tiles_y, true);
  auto* colour_legend = vtkColorLegend::SafeDownCast(chart->GetLegend());
  colour_legend->SetTitle(legend);
  style_axis(ColorLegendAxis::of(colour_legend), legend, options);
  chart->SetShowLegend(true);
  *out = chart.Get();  // the scene holds a reference, so the chart outlives this scope
  return view;
}

// The maps are raster images inside the chart; Debian's libgl2ps is built without PNG support
// and cannot embed them in SVG (the map would be missing), so these charts are PNG only.
ChartOptions png_only(const ChartOptions& options) {
  ChartOptions o = options;
  o.write_svg = false;
  return o;
}

std::string pass_title(const results::TileHeatmap& h) {
  std::string t = h.pass_name.empty() ? std::string("pass") : h.pass_name;
  if (!h.config_id.empty()) t += ", config " + h.config_id;
  return t;
}

}  // namespace

ChartFiles write_tile_cost_heatmap(const results::TileHeatmap& h, const std::string& path_stem,
                                   const ChartOptions& options) {
  check_heatmap(h, "tile heat map " + path_stem);
  const auto [lo_it, hi_it] = std::minmax_element(h.ms.begin(), h.ms.end());
  const double lo = *lo_it, hi = *hi_it > *lo_it ? *hi_it : *lo_it + 1e-6;
  // Viridis stops (matplotlib's perceptually uniform map): readable in grey and for most
  // colour-blind readers.
  vtkNew<vtkColorTransferFunction> colours;
  const double stops[5][3] = {{0.267, 0.005, 0.329},
                              {0.230, 0.322, 0.546},
                              {0.128, 0.567, 0.551},
                              {0.369, 0.789, 0.383},
                              {0.993, 0.906, 0.144}};
  for (int i = 0; i < 5; ++i) {
    colours->AddRGBPoint(lo + (hi - lo) * i / 4.0, stops[i][0], stops[i][1], stops[i][2]);
  }
  auto image = tile_image(h, h.ms);
  vtkChartHistogram2D* chart = nullptr;
  double total = 0.0;
  for (double v : h.ms) total += v;
  auto view = tile_chart(
      h, image, colours,
      fmt::format("Cost per tile: {} (total {:.2f} ms of tile work)", pass_title(h), total),
      "ms per tile", options, &chart);
  return save_chart(view, path_stem, png_only(options));
}

ChartFiles write_tile_bottleneck_map(const results::TileHeatmap& h, const std::string& path_stem,
                                     const ChartOptions& options) {
  check_heatmap(h, "tile bottleneck map " + path_stem);
  if (h.bottleneck.size() != h.ms.size()) {
    throw ReportError("tile bottleneck map " + path_stem +
                      ": heat map has no per-tile bottleneck entries");
  }
  std::vector<std::string> units(h.bottleneck.begin(), h.bottleneck.end());
  std::sort(units.begin(), units.end());
  units.erase(std::unique(units.begin(), units.end()), units.end());
  std::vector<double> index(h.bottleneck.size());
  for (std::size_t i = 0; i < index.size(); ++i) {
    index[i] = static_cast<double>(std::lower_bound(units.begin(), units.end(), h.bottleneck[i]) -
                                   units.begin());
  }
  // Piecewise-constant colours: unit k owns [k - 0.5, k + 0.5].
  vtkNew<vtkColorTransferFunction> colours;
  std::vector<double> at;
  for (std::size_t k = 0; k < units.size(); ++k) {
    const Rgb c = palette_colour(k);
    colours->AddRGBPoint(k - 0.5 + 1e-3, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
    colours->AddRGBPoint(k + 0.5 - 1e-3, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
    at.push_back(static_cast<double>(k));
  }
  auto image = tile_image(h, index);
  vtkChartHistogram2D* chart = nullptr;
  auto view = tile_chart(h, image, colours, "Bottleneck unit per tile: " + pass_title(h),
                         "bottleneck", options, &chart);
  auto* legend = vtkColorLegend::SafeDownCast(chart->GetLegend());
  vtkAxis* legend_axis = ColorLegendAxis::of(legend);
  legend_axis->SetBehavior(vtkAxis::FIXED);
  legend_axis->SetRange(-0.5, units.size() - 0.5);
  set_ticks(legend_axis, at, units);
  return save_chart(view, path_stem, png_only(options));
}

}  // namespace skinsim::reports
