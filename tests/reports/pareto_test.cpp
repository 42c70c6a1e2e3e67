// Pareto front and knee on hand-made cases whose answers are worked out in the comments.
#include "reports/pareto.h"

#include <gtest/gtest.h>

namespace skinsim::reports {
namespace {

results::ConfigResult row(const std::string& id, double ms, double flip) {
  results::ConfigResult r;
  r.id = id;
  r.frame_ms = ms;
  r.frame_ms_low = ms;
  r.frame_ms_high = ms;
  r.quality["flip"] = flip;
  return r;
}

std::vector<std::string> ids(const std::vector<results::ConfigResult>& rows,
                             const std::vector<std::size_t>& idx) {
  std::vector<std::string> out;
  for (std::size_t i : idx) out.push_back(rows[i].id);
  return out;
}

TEST(ParetoFront, DropsDominatedRowsAndSortsByTime) {
  // c (12 ms, 0.30) is beaten by a (10 ms, 0.20) on both; e ties d on time but is worse.
  const std::vector<results::ConfigResult> rows = {row("b", 20, 0.10), row("a", 10, 0.20),
                                                   row("c", 12, 0.30), row("d", 30, 0.05),
                                                   row("e", 30, 0.07)};
  EXPECT_EQ(ids(rows, pareto_front(rows, "flip", false)),
            (std::vector<std::string>{"a", "b", "d"}));
}

TEST(ParetoFront, DirectionOfTheMetricMatters) {
  // Read as "higher is better", 0.30 at 12 ms is now the best value: a, b, d fall behind it
  // except a, which is faster.
  const std::vector<results::ConfigResult> rows = {row("b", 20, 0.10), row("a", 10, 0.20),
                                                   row("c", 12, 0.30), row("d", 30, 0.05)};
  EXPECT_EQ(ids(rows, pareto_front(rows, "flip", true)), (std::vector<std::string>{"a", "c"}));
}

TEST(ParetoFront, IdenticalRowsBothStayAndRowsWithoutTheMetricAreLeftOut) {
  std::vector<results::ConfigResult> rows = {row("x", 10, 0.1), row("y", 10, 0.1),
                                             row("z", 1, 0.0)};
  rows[2].quality.clear();
  EXPECT_EQ(ids(rows, pareto_front(rows, "flip", false)), (std::vector<std::string>{"x", "y"}));
  EXPECT_TRUE(pareto_front(rows, "ssim", true).empty());
}

TEST(ParetoKnee, PicksTheBendOfTheFront) {
  // Front: (10, 0.50) (12, 0.20) (20, 0.15) (30, 0.10). Normalised over the rows within a
  // 33.3 ms budget: time t = (ms-10)/20, loss u = (flip-0.10)/0.40.
  // Distances to (0,0): a 1.0, b hypot(0.1, 0.25) = 0.269, c hypot(0.5, 0.125) = 0.515, d 1.0.
  const std::vector<results::ConfigResult> rows = {row("a", 10, 0.50), row("b", 12, 0.20),
                                                   row("c", 20, 0.15), row("d", 30, 0.10)};
  const auto knee = pareto_knee(rows, "flip", false, 33.3);
  ASSERT_TRUE(knee);
  EXPECT_EQ(rows[*knee].id, "b");
}

TEST(ParetoKnee, IgnoresRowsOverBudget) {
  // With a 15 ms budget only a and b remain: a = (0, 1), b = (1, 0) after normalising; equal
  // distances, so the better quality (b) wins the tie: both fit the budget.
  const std::vector<results::ConfigResult> rows = {row("a", 10, 0.50), row("b", 12, 0.20),
                                                   row("c", 20, 0.15)};
  const auto knee = pareto_knee(rows, "flip", false, 15.0);
  ASSERT_TRUE(knee);
  EXPECT_EQ(rows[*knee].id, "b");
  // A single row within budget is the answer; none within budget gives no answer.
  EXPECT_EQ(rows[*pareto_knee(rows, "flip", false, 11.0)].id, "a");
  EXPECT_FALSE(pareto_knee(rows, "flip", false, 5.0));
}

TEST(ParetoKnee, HigherIsBetterMetric) {
  // SSIM-like: (10, 0.80) (14, 0.95) (30, 0.97). t = (ms-10)/20, loss = (0.97-q)/0.17.
  // a: (0, 1) -> 1; b: (0.2, 0.118) -> 0.232; c: (1, 0) -> 1.
  std::vector<results::ConfigResult> rows = {row("a", 10, 0.80), row("b", 14, 0.95),
                                             row("c", 30, 0.97)};
  EXPECT_EQ(rows[*pareto_knee(rows, "flip", true, 33.3)].id, "b");
}

}  // namespace
}  // namespace skinsim::reports
