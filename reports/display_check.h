// VTK's Debian build renders through an X display (even "offscreen"). Left to itself, a VTK
// render window opens its own connection, once, without retrying, and when that is refused
// (a loaded machine, an xvfb-run server still starting) VTK carries on with no display and
// crashes in XSync (seen twice in a sweep's chart phase while CI ran beside it); on a display
// without a usable OpenGL it aborts. So skinsim opens the display itself, with retries,
// checks its OpenGL, keeps that one connection for the whole process and hands it to every
// chart's render window.
#pragma once

#include <string>

namespace skinsim::reports {

// True if the X display named by DISPLAY is open or can be opened (it is then kept open) and
// offers the OpenGL VTK renders with (GLX, an OpenGL 3.2 core context). Otherwise false, and
// *why (if given) says what is missing and how to run with a display or without charts.
// Creates no VTK object.
bool charts_available(std::string* why);

// How many attempts to open the display were given up on at the check's deadline (a display
// that took the connection and never answered) and are still inside XOpenDisplay. Such an
// attempt holds Xlib's global lock, so no other display can be opened meanwhile, and it may
// return at any time: if it returns while the process exits, it runs in libraries whose
// destructors have already run, and crashes (seen when a test freed the hung connection just
// before its process ended). A process with one pending ends with std::_Exit after flushing
// its output (driver::SweepReportOutcome::display_attempt_pending).
int abandoned_display_attempts();

// The open connection (an Xlib Display*) to the display named by DISPLAY, opened on first use
// and never closed, for vtkRenderWindow::SetDisplayId. Throws ReportError with
// charts_available's message if there is none. If the X server goes away later, skinsim
// prints which display was lost and exits with status 2 (Xlib cannot continue after a lost
// connection); every file written until then is complete, because files are written whole.
void* require_chart_display();

}  // namespace skinsim::reports
