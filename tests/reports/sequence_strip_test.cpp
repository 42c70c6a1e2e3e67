// The "Frames in motion" strips (reports/sequence_sweep.h): a budget within reach of the frame
// times is on the axis; one many times the slowest frame is drawn off scale past a break, so
// the frames spread over the strip instead of bunching at its left end.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "reports/sequence_sweep.h"
#include "results/sequence_summary.h"
#include "results/sweep_table.h"

namespace skinsim::reports {
namespace {

// One configuration whose frames took 1 to 2 ms, against `budget_ms`.
results::SweepTable table_with_budget(double budget_ms) {
  results::ConfigResult row;
  row.id = "c0";
  results::SequenceSummary s;
  s.name = "push-in";
  s.frames = 3;
  s.fps = 30.0;
  s.frame_ms = {1.0, 1.5, 2.0};
  s.p50 = {1.5, 1.4, 1.6};
  s.p95 = s.max = {2.0, 1.9, 2.1};
  results::apply_sequence_summary(row, s);
  results::SweepTable table;
  table.budget_ms = budget_ms;
  table.rows.push_back(row);
  return table;
}

// The x of every line the strip draws in `colour` (ticks "#888", budget "#d00").
std::vector<double> line_xs(const std::string& html, const std::string& colour) {
  // A scan rather than std::regex: GCC 12's <regex> trips -Wmaybe-uninitialized at -O1 (the
  // sanitizer build, -Werror).
  std::vector<double> xs;
  const std::string open = "<line x1=\"", stroke = "stroke=\"" + colour + "\"";
  for (std::size_t at = html.find(open); at != std::string::npos; at = html.find(open, at + 1)) {
    const std::size_t end = html.find('>', at);
    if (html.substr(at, end - at).find(stroke) != std::string::npos) {
      xs.push_back(std::stod(html.substr(at + open.size())));
    }
  }
  return xs;
}

TEST(SequenceStrip, BudgetManyTimesTheFramesIsDrawnOffScale) {
  const std::string html = sequence_sweep_section(table_with_budget(33.3));
  const std::vector<double> ticks = line_xs(html, "#888");
  ASSERT_EQ(ticks.size(), 3u);
  // The slowest frame (2 ms) near the right of the frames' axis (0 to 2.1 * 1.05 ms, 398 px),
  // not at 2 / 35 of the strip as on an axis reaching the budget.
  EXPECT_GT(ticks[2], 300.0);
  EXPECT_NEAR(ticks[0], ticks[2] / 2.0, 0.1);  // still a linear axis from 0
  const std::vector<double> budget = line_xs(html, "#d00");
  ASSERT_EQ(budget.size(), 1u);
  EXPECT_GT(budget[0], ticks[2] + 10.0);
  EXPECT_NE(html.find("budget 33.3 ms"), std::string::npos);
  EXPECT_NE(html.find("off the axis past the break"), std::string::npos);
  EXPECT_NE(html.find("slowest frame's slow end is 6% of it"), std::string::npos) << html;
}

TEST(SequenceStrip, BudgetWithinReachIsOnTheAxis) {
  const std::string html = sequence_sweep_section(table_with_budget(3.0));
  const std::vector<double> ticks = line_xs(html, "#888");
  const std::vector<double> budget = line_xs(html, "#d00");
  ASSERT_EQ(ticks.size(), 3u);
  ASSERT_EQ(budget.size(), 1u);
  EXPECT_NEAR(budget[0] / ticks[2], 3.0 / 2.0, 0.01);  // on the frames' axis
  EXPECT_EQ(html.find("past the break"), std::string::npos);
}

}  // namespace
}  // namespace skinsim::reports
