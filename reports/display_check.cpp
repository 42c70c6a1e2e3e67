#include "reports/display_check.h"

#include <X11/Xlib.h>

#include <chrono>
#include <cstdlib>
#include <thread>

#include "reports/error.h"

namespace skinsim::reports {

namespace {

// A server that xvfb-run has just started can refuse the first connection on a loaded
// machine (seen in CI: the first chart test of a run failed on ':99', the next ones passed),
// so a refused display is tried again for up to 2 s before charts are declared unavailable.
constexpr int kOpenAttempts = 20;
constexpr auto kRetryDelay = std::chrono::milliseconds(100);

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
  for (int attempt = 1; display == nullptr && attempt < kOpenAttempts; ++attempt) {
    std::this_thread::sleep_for(kRetryDelay);
    display = XOpenDisplay(name);
  }
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
