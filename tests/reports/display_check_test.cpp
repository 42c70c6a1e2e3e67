// charts_available() says no, with a useful message, when there is no X display, one that
// never answers, or one without the OpenGL VTK needs; chart functions then throw instead of
// letting VTK abort the process; an X server that goes away while charts are drawn ends the
// process with a message and status 2, not a crash.
#include "reports/display_check.h"

#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "reports/charts.h"
#include "reports/error.h"
#include "tests/hung_display.h"
#include "tests/scoped_env.h"

namespace skinsim::reports {
namespace {

using test::ScopedEnv;

// A sweep row with one pass: enough for write_dram_by_cause_chart.
results::ConfigResult one_pass_row() {
  results::ConfigResult row;
  row.id = "a";
  row.passes = {{"shade", 1.0, "alu", {{"color_store", 1e6}}}};
  return row;
}

TEST(ChartsAvailable, NoWhenDisplayIsUnset) {
  ScopedEnv none("DISPLAY", std::nullopt);
  std::string why;
  EXPECT_FALSE(charts_available(&why));
  EXPECT_NE(why.find("xvfb-run -a"), std::string::npos) << why;
  EXPECT_NE(why.find("--no-charts"), std::string::npos) << why;
  EXPECT_NE(why.find("DISPLAY"), std::string::npos) << why;
  EXPECT_FALSE(charts_available(nullptr));
}

TEST(ChartsAvailable, NoWhenTheDisplayCannotBeOpened) {
  ScopedEnv bogus("DISPLAY", ":4711");  // no X server listens there
  std::string why;
  EXPECT_FALSE(charts_available(&why));
  EXPECT_NE(why.find(":4711"), std::string::npos) << why;
}

// A display that takes the connection but never answers (a hung X server, another program
// on its port) would block Xlib forever: the check gives up after its deadline and says so.
TEST(ChartsAvailable, NoWhenTheDisplayNeverAnswers) {
  test::HungDisplay hung;
  ASSERT_FALSE(hung.name().empty()) << "no free port in 6200-6399";
  const std::string& name = hung.name();
  ScopedEnv use("DISPLAY", name);
  const auto start = std::chrono::steady_clock::now();
  std::string why;
  EXPECT_FALSE(charts_available(&why));
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
  EXPECT_NE(why.find("'" + name + "' did not answer within"), std::string::npos) << why;
  // The attempt given up on is still inside XOpenDisplay, holding Xlib's global lock.
  EXPECT_EQ(abandoned_display_attempts(), 1);
  // Closing the listener resets the waiting connection: the attempt returns and ends. Wait
  // for it, so that it neither returns while this process exits (in a torn-down libX11: it
  // crashed one run in eight under load) nor blocks the next test's XOpenDisplay.
  hung.release();
  const auto released = std::chrono::steady_clock::now();
  while (abandoned_display_attempts() > 0 &&
         std::chrono::steady_clock::now() - released < std::chrono::seconds(10)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_EQ(abandoned_display_attempts(), 0);
}

TEST(ChartsAvailable, ChartFunctionsThrowInsteadOfCrashing) {
  ScopedEnv none("DISPLAY", std::nullopt);
  const results::ConfigResult row = one_pass_row();
  try {
    write_dram_by_cause_chart(row, "never_written");
    FAIL() << "expected ReportError";
  } catch (const ReportError& e) {
    EXPECT_NE(std::string(e.what()).find("X display"), std::string::npos) << e.what();
  }
}

// A private Xvfb on a free display number (Xvfb -displayfd picks it and writes it when it
// accepts connections), with `options` added to its command line, killed when the scope
// ends. name() is empty if it could not start.
class PrivateXServer {
 public:
  explicit PrivateXServer(std::vector<std::string> options = {}) {
    int ready[2];
    if (pipe(ready) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      close(ready[0]);
      std::vector<std::string> args = {"Xvfb",      "-displayfd", std::to_string(ready[1]),
                                       "-nolisten", "tcp",        "-screen",
                                       "0",         "640x480x24"};
      args.insert(args.end(), options.begin(), options.end());
      std::vector<char*> argv;
      for (std::string& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      execvp("Xvfb", argv.data());
      _exit(127);
    }
    close(ready[1]);
    std::string number;
    pollfd wait_for{ready[0], POLLIN, 0};
    char c = 0;
    while (pid_ > 0 && poll(&wait_for, 1, 10000) == 1 && read(ready[0], &c, 1) == 1 && c != '\n') {
      number += c;
    }
    close(ready[0]);
    if (!number.empty()) name_ = ":" + number;
  }
  ~PrivateXServer() { stop(); }
  PrivateXServer(const PrivateXServer&) = delete;
  PrivateXServer& operator=(const PrivateXServer&) = delete;

  const std::string& name() const { return name_; }
  void stop() {
    if (pid_ <= 0) return;
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }

 private:
  pid_t pid_ = -1;
  std::string name_;
};

// VTK aborts the process on a display without GLX ("Could not find a decent config"); the
// check finds it first, names it, and the chart functions throw instead.
TEST(ChartsAvailable, NoWhenTheDisplayHasNoOpenGL) {
  // Kept until the process ends: skinsim keeps a display name's connection for the process
  // (display_check.h), so a later test's Xvfb must not get this one's number.
  static PrivateXServer server({"-extension", "GLX"});
  if (server.name().empty()) GTEST_SKIP() << "cannot start Xvfb (is the xvfb package installed?)";
  ScopedEnv use("DISPLAY", server.name());
  std::string why;
  EXPECT_FALSE(charts_available(&why));
  EXPECT_NE(why.find("X display '" + server.name() + "': it has no GLX extension"),
            std::string::npos)
      << why;
  EXPECT_NE(why.find("--no-charts"), std::string::npos) << why;
  const results::ConfigResult row = one_pass_row();
  EXPECT_THROW(write_dram_by_cause_chart(row, ::testing::TempDir() + "no_glx/dram"), ReportError);
}

// A server that gives indirect contexts (+iglx) gives only OpenGL 1.4, on which VTK crashes
// ("GLEW could not be initialized"); Mesa's libGL asks for indirect ones when told to, as it
// must over ssh -X.
TEST(ChartsAvailable, NoWhenTheDisplayGivesOnlyAnOldOpenGL) {
  // Kept until the process ends: skinsim keeps a display name's connection for the process
  // (display_check.h), so a later test's Xvfb must not get this one's number.
  static PrivateXServer server({"+iglx"});
  if (server.name().empty()) GTEST_SKIP() << "cannot start Xvfb (is the xvfb package installed?)";
  ScopedEnv use("DISPLAY", server.name());
  ScopedEnv indirect("LIBGL_ALWAYS_INDIRECT", "1");
  std::string why;
  EXPECT_FALSE(charts_available(&why));
  EXPECT_NE(why.find("X display '" + server.name() + "': it cannot create an OpenGL 3.2"),
            std::string::npos)
      << why;
}

TEST(ChartDisplayDeathTest, ALostXServerEndsTheProcessWithStatus2AndSaysWhichDisplay) {
  PrivateXServer server;
  if (server.name().empty()) GTEST_SKIP() << "cannot start Xvfb (is the xvfb package installed?)";
  ScopedEnv use("DISPLAY", server.name());
  const results::ConfigResult row = one_pass_row();
  const std::string dir = ::testing::TempDir() + "lost_display_charts";
  // Only the forked child connects, so this process keeps no connection to the killed server
  // (a later test's Xvfb may get the same display number).
  EXPECT_EXIT(
      {
        if (!charts_available(nullptr)) std::_Exit(3);
        server.stop();  // the server dies under the open connection
        for (;;) write_dram_by_cause_chart(row, dir + "/dram");
      },
      ::testing::ExitedWithCode(2), "lost the connection to X display '" + server.name() + "'");
}

}  // namespace
}  // namespace skinsim::reports
