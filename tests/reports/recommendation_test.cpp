// One recommendation per group; invisible differences are ties won by the cheaper row.
#include "reports/recommendation.h"

#include <gtest/gtest.h>

namespace skinsim::reports {
namespace {

// A row of `group` at `ms` with FLIP `flip` against the reference; `visible_vs_best`: whether
// its frame differs visibly from the group's best row (`best`).
results::ConfigResult row(const std::string& id, const std::string& group, double ms, double flip,
                          const std::string& best, bool visible_vs_best) {
  results::ConfigResult r;
  r.id = id;
  r.group = group;
  r.frame_ms = ms;
  r.frame_ms_low = ms * 0.9;
  r.frame_ms_high = ms * 1.3;
  r.energy_mj = ms / 8.0;  // 125 mW over the frame
  r.energy_mj_low = r.energy_mj * 0.5;
  r.energy_mj_high = r.energy_mj * 2.0;
  r.quality["flip_skin"] = flip;
  r.vs_best = results::FrameComparison{best, id == best ? 0.0 : 0.01, 0.05,
                                       visible_vs_best ? 500.0 : 3.0, visible_vs_best};
  return r;
}

TEST(Recommendation, AnInvisibleDifferenceIsATieAndTheCheaperWins) {
  results::SweepTable t;
  t.budget_ms = 30.0;
  t.rows = {row("fine", "ipad4", 25.0, 0.0800, "fine", false),
            row("cheap", "ipad4", 12.0, 0.0801, "fine", false),  // 0.0001 worse: noise
            row("cheaper_visible", "ipad4", 10.0, 0.0900, "fine", true)};
  const std::vector<Recommendation> r = recommend(t, "flip_skin");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].chosen, 1u);
  EXPECT_EQ(r[0].best, 0u);
  EXPECT_TRUE(r[0].indistinguishable);
  EXPECT_NE(r[0].verdict.find("not visibly different from the best, fine"), std::string::npos)
      << r[0].verdict;
  EXPECT_NE(r[0].verdict.find("saves 13.00 ms"), std::string::npos) << r[0].verdict;
  EXPECT_NE(r[0].verdict.find("12.00 ms (10.80 to 15.60) and 1.500 mJ (0.750 to 3.000) per frame"),
            std::string::npos)
      << r[0].verdict;
}

TEST(Recommendation, DevicesAreNeverComparedAcrossGroups) {
  results::SweepTable t;
  t.budget_ms = 30.0;
  t.rows = {row("a_ipad", "ipad4", 20.0, 0.08, "a_ipad", false),
            row("a_iphone", "iphone5", 28.0, 0.07, "b_iphone", false),
            row("b_ipad", "ipad4", 15.0, 0.081, "a_ipad", false),
            row("b_iphone", "iphone5", 35.0, 0.069, "b_iphone", false)};
  const std::vector<Recommendation> r = recommend(t, "flip_skin");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].group, "ipad4");
  EXPECT_EQ(r[0].chosen, 2u);  // b_ipad: cheaper, not visibly worse
  EXPECT_EQ(r[1].group, "iphone5");
  // The iPhone's best row (b_iphone) is over budget; a_iphone is not visibly different from
  // it and fits. The iPad's rows play no part.
  EXPECT_EQ(r[1].best, 3u);
  EXPECT_EQ(r[1].chosen, 1u);
}

TEST(Recommendation, WhenEverythingInBudgetIsVisiblyWorseTheKneeIsChosenAndSaidSo) {
  results::SweepTable t;
  t.budget_ms = 20.0;
  t.rows = {row("best", "g", 40.0, 0.05, "best", false),  // over budget
            row("mid", "g", 18.0, 0.07, "best", true), row("low", "g", 8.0, 0.09, "best", true)};
  const std::vector<Recommendation> r = recommend(t, "flip_skin");
  ASSERT_EQ(r.size(), 1u);
  ASSERT_TRUE(r[0].chosen.has_value());
  EXPECT_FALSE(r[0].indistinguishable);
  EXPECT_NE(r[0].verdict.find("differs visibly"), std::string::npos) << r[0].verdict;
}

TEST(Recommendation, NothingWithinBudgetIsNoRecommendation) {
  results::SweepTable t;
  t.budget_ms = 5.0;
  t.rows = {row("a", "g", 10.0, 0.05, "a", false)};
  const std::vector<Recommendation> r = recommend(t, "flip_skin");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].chosen.has_value());
  EXPECT_NE(r[0].verdict.find("no configuration fits the 5.0 ms budget"), std::string::npos);
}

}  // namespace
}  // namespace skinsim::reports

namespace skinsim::reports {
namespace {

// Rows of group "g" at `ms` (range low..high), FLIP `flip`, visibly different from "best" or
// not.
results::ConfigResult ranged(const std::string& id, double ms, double low, double high, double flip,
                             bool visible_vs_best) {
  results::ConfigResult r = row(id, "g", ms, flip, "best", visible_vs_best);
  r.frame_ms_low = low;
  r.frame_ms_high = high;
  return r;
}

TEST(Recommendation, SaysWhenTheRangeStraddlesTheBudgetAndNamesTheSafeChoice) {
  results::SweepTable t;
  t.budget_ms = 33.3;
  t.rows = {ranged("best", 40.0, 30.0, 60.0, 0.05, false),
            ranged("cheap", 23.17, 17.11, 43.06, 0.0501, false),  // straddles
            ranged("safe", 25.0, 20.0, 31.0, 0.0502, false),      // fits at its slow end
            ranged("visible", 10.0, 8.0, 12.0, 0.09, true)};
  std::vector<Recommendation> r = recommend(t, "flip_skin");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].chosen, 1u);
  EXPECT_TRUE(r[0].straddles_budget);
  EXPECT_EQ(r[0].safe, 2u);
  EXPECT_NE(r[0].range_note.find("Its modelled range, 17.11 to 43.06 ms, straddles the 33.3 ms "
                                 "budget"),
            std::string::npos)
      << r[0].range_note;
  EXPECT_NE(r[0].range_note.find("fits even at its slow end is safe at 25.00 ms"),
            std::string::npos)
      << r[0].range_note;
  // No tie fits at its slow end: said so.
  t.rows[2].frame_ms_high = 34.0;
  r = recommend(t, "flip_skin");
  EXPECT_FALSE(r[0].safe.has_value());
  EXPECT_NE(r[0].range_note.find("No configuration that looks the same as the best fits"),
            std::string::npos)
      << r[0].range_note;
  // A range inside the budget: said so too.
  t.budget_ms = 50.0;
  r = recommend(t, "flip_skin");
  EXPECT_FALSE(r[0].straddles_budget);
  EXPECT_NE(r[0].range_note.find("whole modelled range, 17.11 to 43.06 ms, is within the 50.0 "
                                 "ms budget"),
            std::string::npos)
      << r[0].range_note;
}

TEST(Recommendation, NamesTheRunnerUpAndWhyItLost) {
  results::SweepTable t;
  t.budget_ms = 30.0;
  t.rows = {ranged("best", 25.0, 20.0, 28.0, 0.05, false),
            ranged("tie", 20.0, 16.0, 24.0, 0.0501, false),
            ranged("cheap_visible", 8.08, 6.0, 10.0, 0.09, true)};
  std::vector<Recommendation> r = recommend(t, "flip_skin");
  EXPECT_EQ(r[0].chosen, 1u);
  EXPECT_EQ(r[0].runner_up, 0u);  // the next tie
  EXPECT_NE(r[0].runner_up_note.find("Runner-up: best at 25.00 ms (20.00 to 28.00) and 3.125 mJ "
                                     "(1.562 to 6.250) per frame; it also looks the same as the "
                                     "best, but costs 5.00 ms more"),
            std::string::npos)
      << r[0].runner_up_note;
  // With the best out of budget, the only other candidate differs visibly.
  t.rows[0].frame_ms = 35.0;
  t.rows[0].frame_ms_high = 40.0;
  r = recommend(t, "flip_skin");
  EXPECT_EQ(r[0].runner_up, 2u);
  EXPECT_NE(r[0].runner_up_note.find("it saves 11.92 ms but differs visibly from the best"),
            std::string::npos)
      << r[0].runner_up_note;
  // Everything within budget visible: the knee wins, the runner-up is the next knee.
  t.rows[1].vs_best->visible = true;
  r = recommend(t, "flip_skin");
  ASSERT_TRUE(r[0].runner_up.has_value());
  EXPECT_NE(r[0].runner_up_note.find("further from the knee"), std::string::npos)
      << r[0].runner_up_note;
  // One row: no runner-up.
  t.rows.resize(1);
  t.rows[0].frame_ms = 25.0;
  r = recommend(t, "flip_skin");
  EXPECT_FALSE(r[0].runner_up.has_value());
  EXPECT_TRUE(r[0].runner_up_note.empty());
}

}  // namespace
}  // namespace skinsim::reports
