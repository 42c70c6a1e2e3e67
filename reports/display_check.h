// VTK's Debian build renders through an X display (even "offscreen"); creating a render
// window without one aborts the process. Check first, and fail with a message instead.
#pragma once

#include <string>

namespace skinsim::reports {

// True if an X display can be opened (DISPLAY set and XOpenDisplay succeeds). Otherwise false,
// and *why (if given) says what is missing and how to run with a display or without charts.
// Creates no VTK object.
bool charts_available(std::string* why);

// Throws ReportError with charts_available's message if charts cannot be drawn.
void require_charts_available();

}  // namespace skinsim::reports
