// charts_available() says no, with a useful message, when there is no X display; chart
// functions then throw instead of letting VTK abort the process.
#include "reports/display_check.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "reports/charts.h"
#include "reports/error.h"

namespace skinsim::reports {
namespace {

// Sets DISPLAY (or unsets it, for nullopt) for the scope, then restores it.
class ScopedDisplay {
 public:
  explicit ScopedDisplay(const std::optional<std::string>& value) {
    if (const char* old = std::getenv("DISPLAY")) old_ = old;
    if (value)
      ::setenv("DISPLAY", value->c_str(), 1);
    else
      ::unsetenv("DISPLAY");
  }
  ~ScopedDisplay() {
    if (old_)
      ::setenv("DISPLAY", old_->c_str(), 1);
    else
      ::unsetenv("DISPLAY");
  }

 private:
  std::optional<std::string> old_;
};

TEST(ChartsAvailable, NoWhenDisplayIsUnset) {
  ScopedDisplay none(std::nullopt);
  std::string why;
  EXPECT_FALSE(charts_available(&why));
  EXPECT_NE(why.find("xvfb-run -a"), std::string::npos) << why;
  EXPECT_NE(why.find("--no-charts"), std::string::npos) << why;
  EXPECT_NE(why.find("DISPLAY"), std::string::npos) << why;
  EXPECT_FALSE(charts_available(nullptr));
}

TEST(ChartsAvailable, NoWhenTheDisplayCannotBeOpened) {
  ScopedDisplay bogus(std::string(":4711"));  // no X server listens there
  std::string why;
  EXPECT_FALSE(charts_available(&why));
  EXPECT_NE(why.find(":4711"), std::string::npos) << why;
}

TEST(ChartsAvailable, ChartFunctionsThrowInsteadOfCrashing) {
  ScopedDisplay none(std::nullopt);
  ConfigResult row;
  row.id = "a";
  row.passes = {{"shade", 1.0, "alu", {{"color_store", 1e6}}}};
  try {
    write_dram_by_cause_chart(row, "never_written");
    FAIL() << "expected ReportError";
  } catch (const ReportError& e) {
    EXPECT_NE(std::string(e.what()).find("X display"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace skinsim::reports
