#include "reports/display_check.h"

#include <X11/Xlib.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
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

// Xlib calls this when a connection breaks (the server exited or was killed) and exits the
// process when it returns, so it never returns: it names the display and exits with 2.
int report_lost_display(Display* display) {
  std::fflush(stdout);
  std::fprintf(stderr,
               "skinsim: error: lost the connection to X display '%s' while drawing charts (its "
               "X server exited); files written before this are complete: run the same command "
               "again with a display, or pass --no-charts\n",
               DisplayString(display));
  std::fflush(stderr);
  std::_Exit(2);
}

// One connection per display name, opened once and kept: render windows that were handed a
// connection hold it until they are destroyed, so it is never closed under them.
class OpenDisplays {
 public:
  Display* open(const std::string& name) {
    const std::lock_guard lock(mutex_);
    if (auto it = displays_.find(name); it != displays_.end()) return it->second;
    Display* display = XOpenDisplay(name.c_str());
    for (int attempt = 1; display == nullptr && attempt < kOpenAttempts; ++attempt) {
      std::this_thread::sleep_for(kRetryDelay);
      display = XOpenDisplay(name.c_str());
    }
    if (display == nullptr) return nullptr;
    XSetIOErrorHandler(report_lost_display);
    displays_.emplace(name, display);
    return display;
  }

 private:
  std::mutex mutex_;
  std::map<std::string, Display*> displays_;
};

// The display named by DISPLAY, or nullptr with *why set.
Display* display_from_environment(std::string* why) {
  static OpenDisplays displays;
  const char* name = std::getenv("DISPLAY");
  if (name == nullptr || *name == '\0') {
    if (why) *why = std::string(kHowTo) + " (the DISPLAY environment variable is not set)";
    return nullptr;
  }
  Display* display = displays.open(name);
  if (display == nullptr && why) {
    *why = std::string(kHowTo) + " (cannot open X display '" + name + "')";
  }
  return display;
}

}  // namespace

bool charts_available(std::string* why) {
  const bool open = display_from_environment(why) != nullptr;
  if (open && why) why->clear();
  return open;
}

void* require_chart_display() {
  std::string why;
  Display* display = display_from_environment(&why);
  if (display == nullptr) throw ReportError(why);
  return display;
}

}  // namespace skinsim::reports
