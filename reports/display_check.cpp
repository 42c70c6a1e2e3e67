#include "reports/display_check.h"

#include <X11/Xlib.h>

#include <cstdlib>

#include "reports/error.h"

namespace skinsim::reports {

namespace {

constexpr const char* kHowTo =
    "charts need an X display: run under `xvfb-run -a skinsim ...` or pass --no-charts";

}  // namespace

bool charts_available(std::string* why) {
  const char* name = std::getenv("DISPLAY");
  if (name == nullptr || *name == '\0') {
    if (why) *why = std::string(kHowTo) + " (the DISPLAY environment variable is not set)";
    return false;
  }
  Display* display = XOpenDisplay(name);
  if (display == nullptr) {
    if (why) *why = std::string(kHowTo) + " (cannot open X display '" + name + "')";
    return false;
  }
  XCloseDisplay(display);
  if (why) why->clear();
  return true;
}

void require_charts_available() {
  std::string why;
  if (!charts_available(&why)) throw ReportError(why);
}

}  // namespace skinsim::reports
