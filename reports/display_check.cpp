#include "reports/display_check.h"

#include <GL/glx.h>
#include <X11/Xlib.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "reports/error.h"

namespace skinsim::reports {

namespace {

// A server that xvfb-run has just started can refuse the first connection on a loaded
// machine (seen in CI: the first chart test of a run failed on ':99', the next ones passed),
// so a refused display is tried again for up to 2 s before charts are declared unavailable.
constexpr int kOpenAttempts = 20;
constexpr auto kRetryDelay = std::chrono::milliseconds(100);
// Xlib waits for a display's answer without limit: a display whose port takes connections but
// never answers (a hung X server, another program listening there) or whose host drops the
// packets (a stale DISPLAY naming a machine that is down) would hold skinsim forever. After
// this long it counts as unavailable.
constexpr auto kAnswerDeadline = std::chrono::seconds(10);

constexpr const char* kHowTo =
    "charts need an X display with OpenGL (GLX): run under `xvfb-run -a skinsim ...` or pass "
    "--no-charts";

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

// Set by note_x_error while missing_opengl creates its test context (under OpenDisplays'
// lock, so one at a time).
bool x_error_seen = false;
int note_x_error(Display*, XErrorEvent*) {
  x_error_seen = true;
  return 0;
}

// Empty if VTK can draw on `display`, else what the display lacks. VTK 9.1 aborts the process
// where it finds no GLX frame-buffer configuration ("Could not find a decent config"), and
// crashes where it gets no OpenGL 3.2 ("GLEW could not be initialized"), so this asks for what
// vtkXOpenGLRenderWindow asks for: a configuration for an RGBA window with alpha and depth,
// and on it a core context of OpenGL 3.2 or later through GLX_ARB_create_context (VTK falls
// back to a legacy context only to fail with it). A display without GLX (a VNC server), a
// server that refuses indirect contexts (ssh -X to a modern Xorg), or one that gives them only
// OpenGL 1.4 (indirect GLX enabled) fails here instead.
std::string missing_opengl(Display* display) {
  int error_base = 0, event_base = 0;
  if (!glXQueryExtension(display, &error_base, &event_base)) return "it has no GLX extension";
  // Attribute, value pairs.
  // clang-format off
  const int attributes[] = {GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, GLX_RENDER_TYPE, GLX_RGBA_BIT,
                            GLX_RED_SIZE, 1, GLX_GREEN_SIZE, 1, GLX_BLUE_SIZE, 1,
                            GLX_ALPHA_SIZE, 1, GLX_DEPTH_SIZE, 1, None};
  const int core_3_2[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 2,
                          GLX_CONTEXT_PROFILE_MASK_ARB, GLX_CONTEXT_CORE_PROFILE_BIT_ARB, None};
  // clang-format on
  const auto create_context = reinterpret_cast<PFNGLXCREATECONTEXTATTRIBSARBPROC>(
      glXGetProcAddressARB(reinterpret_cast<const GLubyte*>("glXCreateContextAttribsARB")));
  if (create_context == nullptr) return "its GLX cannot create OpenGL 3.2 contexts";
  int count = 0;
  GLXFBConfig* configs = glXChooseFBConfig(display, DefaultScreen(display), attributes, &count);
  if (configs == nullptr || count == 0) {
    if (configs != nullptr) XFree(configs);
    return "it offers no OpenGL frame-buffer configuration with colour, alpha and depth";
  }
  // A refused context arrives as an X error, which Xlib's default handler turns into exit(1).
  x_error_seen = false;
  const XErrorHandler previous = XSetErrorHandler(note_x_error);
  GLXContext context = create_context(display, configs[0], nullptr, True, core_3_2);
  XSync(display, False);
  XSetErrorHandler(previous);
  XFree(configs);
  if (context != nullptr) glXDestroyContext(display, context);
  if (context == nullptr || x_error_seen) {
    return "it cannot create an OpenGL 3.2 core context, which VTK needs";
  }
  return "";
}

// Attempts given up on at their deadline whose XOpenDisplay has not returned yet.
std::atomic<int> abandoned_attempts{0};

// XOpenDisplay(name), or nullopt when it has not returned by `deadline`. The attempt runs on
// a thread of its own; one still waiting at the deadline is left to finish alone (counted in
// abandoned_attempts until it does), and a connection it opens after that is never used.
std::optional<Display*> open_before(const std::string& name,
                                    std::chrono::steady_clock::time_point deadline) {
  struct Attempt {
    std::mutex mutex;
    std::condition_variable done;
    bool finished = false;
    bool abandoned = false;
    Display* display = nullptr;
  };
  const auto attempt = std::make_shared<Attempt>();
  std::thread([attempt, name] {
    Display* display = XOpenDisplay(name.c_str());
    const std::lock_guard lock(attempt->mutex);
    attempt->display = display;
    attempt->finished = true;
    if (attempt->abandoned) --abandoned_attempts;
    attempt->done.notify_one();
  }).detach();
  std::unique_lock lock(attempt->mutex);
  if (!attempt->done.wait_until(lock, deadline, [&] { return attempt->finished; })) {
    attempt->abandoned = true;
    ++abandoned_attempts;
    return std::nullopt;
  }
  return attempt->display;
}

// One connection per display name, opened once and kept: render windows that were handed a
// connection hold it until they are destroyed, so it is never closed under them.
class OpenDisplays {
 public:
  // The display, or nullptr with *why saying what is wrong.
  Display* open(const std::string& name, std::string* why) {
    const std::lock_guard lock(mutex_);
    auto it = displays_.find(name);
    if (it == displays_.end()) it = displays_.emplace(name, connect(name)).first;
    if (why) *why = it->second.problem;
    return it->second.problem.empty() ? it->second.display : nullptr;
  }

 private:
  struct Connection {
    Display* display = nullptr;
    std::string problem;  // empty when charts can be drawn on `display`
  };

  static Connection connect(const std::string& name) {
    // Connections are opened on other threads than the one drawing, and an abandoned attempt
    // may still be inside Xlib, so Xlib must lock: XInitThreads, before any other Xlib call.
    static const bool threads = XInitThreads() != 0;
    if (!threads) return {nullptr, std::string(kHowTo) + " (Xlib cannot be used from threads)"};
    const auto deadline = std::chrono::steady_clock::now() + kAnswerDeadline;
    Display* display = nullptr;
    for (int attempt = 0; display == nullptr && attempt < kOpenAttempts; ++attempt) {
      if (attempt > 0) std::this_thread::sleep_for(kRetryDelay);
      const std::optional<Display*> opened = open_before(name, deadline);
      if (!opened) {
        return {nullptr, std::string(kHowTo) + " (X display '" + name + "' did not answer within " +
                             std::to_string(kAnswerDeadline.count()) + " s)"};
      }
      display = *opened;
    }
    if (display == nullptr) {
      return {nullptr, std::string(kHowTo) + " (cannot open X display '" + name + "')"};
    }
    XSetIOErrorHandler(report_lost_display);
    const std::string missing = missing_opengl(display);
    if (!missing.empty()) {
      return {display, std::string(kHowTo) + " (X display '" + name + "': " + missing + ")"};
    }
    return {display, ""};
  }

  std::mutex mutex_;
  std::map<std::string, Connection> displays_;
};

// The display named by DISPLAY, or nullptr with *why set.
Display* display_from_environment(std::string* why) {
  static OpenDisplays displays;
  const char* name = std::getenv("DISPLAY");
  if (name == nullptr || *name == '\0') {
    if (why) *why = std::string(kHowTo) + " (the DISPLAY environment variable is not set)";
    return nullptr;
  }
  return displays.open(name, why);
}

}  // namespace

int abandoned_display_attempts() {
  return abandoned_attempts.load();
}

bool charts_available(std::string* why) {
  return display_from_environment(why) != nullptr;
}

void* require_chart_display() {
  std::string why;
  Display* display = display_from_environment(&why);
  if (display == nullptr) throw ReportError(why);
  return display;
}

}  // namespace skinsim::reports
