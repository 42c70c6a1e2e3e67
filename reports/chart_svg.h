// A chart window as SVG, through GL2PS (VTK's vector export).
#pragma once

#include <string>

class vtkRenderWindow;

namespace skinsim::reports {

// Writes `window`'s chart to `path` atomically: lines, markers and text as vectors (text as
// paths, so it looks as in the PNG whatever fonts the viewer has), background transparent.
// Throws ReportError when GL2PS cannot write it or the file is cut short.
void write_chart_svg(vtkRenderWindow* window, const std::string& path);

}  // namespace skinsim::reports
