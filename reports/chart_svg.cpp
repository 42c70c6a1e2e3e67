#include "reports/chart_svg.h"

#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLGL2PSExporter.h>
#include <vtkOpenGLGL2PSHelper.h>
#include <vtkRenderWindow.h>
#include <vtk_gl2ps.h>

#include <cstdio>
#include <filesystem>
#include <memory>

#include "io/atomic_file.h"
#include "io/read_file.h"
#include "io/temp_files.h"
#include "reports/error.h"

namespace skinsim::reports {

namespace fs = std::filesystem;

namespace {

// vtkOpenGLGL2PSHelper's setters are protected, for its friend vtkOpenGLGL2PSExporter only. A
// pointer to a protected member may be formed through a class derived from its own (C++20
// [class.protected]), so this class names them for VectorOnlyExporter below.
class HelperSetters : vtkOpenGLGL2PSHelper {
 public:
  static void set_up(vtkOpenGLGL2PSHelper* helper, vtkRenderWindow* window, bool text_as_path) {
    (helper->*&HelperSetters::SetTextAsPath)(text_as_path);
    (helper->*&HelperSetters::SetRenderWindow)(window);
  }
  static void set_state(vtkOpenGLGL2PSHelper* helper, State state) {
    (helper->*&HelperSetters::SetActiveState)(state);
  }
};

// vtkOpenGLGL2PSExporter::WriteData without its two steps that produce nothing here
// (VTK 9.1, IO/ExportGL2PS/vtkOpenGLGL2PSExporter.cxx). It first renders the window twice more
// and reads it back as a float image to hand GL2PS as the page's background, which Debian's
// libgl2ps, built without PNG, cannot embed in an SVG: it drops it with a warning on stderr.
// And it renders the window again at the end, which nothing reads after the export. Both took
// about 0.4 s of a sweep's 2.2 s of charts, on the one thread VTK draws on (docs/performance.md).
// GL2PS receives the vector pass alone, as from VTK's exporter: with the same settings the
// SVGs were the same below their header (title, creator, creation date).
class VectorOnlyExporter : public vtkOpenGLGL2PSExporter {
 public:
  static VectorOnlyExporter* New();
  bool succeeded() const { return succeeded_; }

 protected:
  void WriteData() override {
    const std::string name = std::string(this->FilePrefix) + "." + this->GetFileExtension();
    const std::unique_ptr<std::FILE, decltype(&std::fclose)> file(std::fopen(name.c_str(), "wb"),
                                                                  std::fclose);
    if (!file) return;
    const int* size = this->RenderWindow->GetSize();
    GLint viewport[4] = {0, 0, size[0], size[1]};
    // As VTK's exporter: GL2PS takes the primitives VTK hands it rather than reading OpenGL's
    // feedback buffer, and draws no background of its own.
    const GLint options = (this->GetGL2PSOptions() | GL2PS_NO_OPENGL_CONTEXT | GL2PS_NO_BLENDING) &
                          ~GL2PS_DRAW_BACKGROUND;
    vtkNew<vtkOpenGLGL2PSHelper> helper;
    vtkOpenGLGL2PSHelper::SetInstance(helper);
    HelperSetters::set_up(helper, this->RenderWindow, this->TextAsPath);
    if (gl2psBeginPage("skinsim chart", "skinsim", viewport, this->GetGL2PSFormat(),
                       this->GetGL2PSSort(), options, GL_RGBA, 0, nullptr, 0, 0, 0, 0, file.get(),
                       name.c_str()) == GL2PS_SUCCESS) {
      HelperSetters::set_state(helper, vtkOpenGLGL2PSHelper::Capture);
      this->RenderWindow->Render();
      HelperSetters::set_state(helper, vtkOpenGLGL2PSHelper::Inactive);
      succeeded_ = gl2psEndPage() == GL2PS_SUCCESS;
    }
    vtkOpenGLGL2PSHelper::SetInstance(nullptr);
  }

 private:
  bool succeeded_ = false;

 public:
  // Last: it takes no semicolon, which clang-format would read as continuing onto the next line.
  vtkTypeMacro(VectorOnlyExporter, vtkOpenGLGL2PSExporter)
};
vtkStandardNewMacro(VectorOnlyExporter);

}  // namespace

void write_chart_svg(vtkRenderWindow* window, const std::string& path) {
  // GL2PS writes only to a file named PREFIX.svg and does not report write errors: export to a
  // temporary, read it back whole (an SVG ends with its closing tag), then write it checked.
  const fs::path tmp_prefix = io::temporary_path_beside(path);
  const fs::path tmp = tmp_prefix.string() + ".svg";
  vtkNew<VectorOnlyExporter> exporter;
  exporter->SetRenderWindow(window);
  exporter->SetFileFormatToSVG();
  exporter->SetFilePrefix(tmp_prefix.c_str());
  exporter->CompressOff();
  exporter->UsePainterSettings();  // chart items are painted back to front: no depth sort
  // Text as SVG <text> is laid out with the viewer's fonts, whose widths differ from VTK's:
  // axis titles then ran into the tick labels (headless Chromium). As paths it is VTK's glyphs.
  exporter->TextAsPathOn();
  exporter->Write();
  std::string svg;
  try {
    svg = io::read_regular_file(tmp, "exported chart");
  } catch (const io::InputError&) {
    svg.clear();
  }
  std::error_code ec;
  fs::remove(tmp, ec);
  if (!exporter->succeeded() || svg.find("</svg>") == std::string::npos) {
    throw ReportError("cannot write chart " + path + " (GL2PS export failed or was cut short)");
  }
  io::write_file_atomically(path, svg);
}

}  // namespace skinsim::reports
