#include "reports/chart_canvas.h"

#include <unistd.h>
#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkGL2PSExporter.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "io/atomic_file.h"
#include "io/read_file.h"
#include "io/temp_files.h"
#include "quality/error.h"
#include "quality/image.h"
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

void place_legend_outside(vtkChartXY* chart, const ChartOptions& options) {
  chart->SetShowLegend(true);
  vtkChartLegend* legend = chart->GetLegend();
  legend->SetInline(false);
  legend->SetLabelSize(options.legend_font_size);
  legend->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  legend->SetVerticalAlignment(vtkChartLegend::TOP);
}

namespace {

// Debian's libgl2ps prints "GL2PS warning: GL2PS must be compiled with PNG support ..." on
// stderr for every SVG (the background image it cannot embed, see write_svg). It is expected
// and harmless, so while GL2PS runs stderr goes to a temporary file, and everything in it but
// that warning is printed again afterwards (another thread's message is delayed, not lost).
class Gl2psWarningFilter {
 public:
  Gl2psWarningFilter() : file_(std::tmpfile()) {
    std::fflush(stderr);
    saved_ = file_ ? dup(STDERR_FILENO) : -1;
    if (saved_ >= 0) dup2(fileno(file_), STDERR_FILENO);
  }
  ~Gl2psWarningFilter() {
    if (saved_ >= 0) {
      std::fflush(stderr);
      dup2(saved_, STDERR_FILENO);
      close(saved_);
      std::rewind(file_);
      char line[4096];
      while (std::fgets(line, sizeof line, file_)) {
        if (!std::strstr(line, "must be compiled with PNG support")) std::fputs(line, stderr);
      }
    }
    if (file_) std::fclose(file_);
  }
  Gl2psWarningFilter(const Gl2psWarningFilter&) = delete;
  Gl2psWarningFilter& operator=(const Gl2psWarningFilter&) = delete;

 private:
  std::FILE* file_;
  int saved_ = -1;
};

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
    quality::write_png_u8(path, size[0], size[1], 3, top_down);
  } catch (const quality::QualityError& e) {
    throw ReportError("cannot write chart " + path + ": " + e.what());
  }
}

void write_svg(vtkRenderWindow* window, const std::string& path) {
  // GL2PS writes only to a file named PREFIX.svg and does not report write errors: export to a
  // temporary, read it back whole (an SVG ends with its closing tag), then write it checked.
  const fs::path tmp_prefix = io::temporary_path_beside(path);
  const fs::path tmp = tmp_prefix.string() + ".svg";
  vtkNew<vtkGL2PSExporter> exporter;
  exporter->SetRenderWindow(window);
  exporter->SetFileFormatToSVG();
  exporter->SetFilePrefix(tmp_prefix.c_str());
  exporter->CompressOff();
  // The OpenGL2 backend always hands GL2PS the background as an image, which Debian's libgl2ps
  // (built without PNG) cannot embed: it warns once and the SVG background stays transparent.
  exporter->UsePainterSettings();  // chart items are painted back to front: no depth sort
  {
    const Gl2psWarningFilter quiet;
    exporter->Write();
  }
  std::string svg;
  try {
    svg = io::read_regular_file(tmp, "exported chart");
  } catch (const io::InputError&) {
    svg.clear();
  }
  std::error_code ec;
  fs::remove(tmp, ec);
  if (svg.find("</svg>") == std::string::npos) {
    throw ReportError("cannot write chart " + path + " (GL2PS export failed or was cut short)");
  }
  io::write_file_atomically(path, svg);
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
    // GL2PS re-renders in feedback mode and leaves the window so: every chart saves last.
    write_svg(window, files.svg);
  }
  return files;
}

}  // namespace skinsim::reports
