// Evaluating limits on a synthetic measurement: pass/fail, margins, baseline-relative
// bounds, the errors for unknown passes and missing baselines, and the failure messages.
#include "budget/evaluate.h"

#include <gtest/gtest.h>

#include "budget/check_table.h"
#include "budget/error.h"

namespace skinsim::budget {
namespace {

Measurement synthetic() {
  Measurement m;
  m.passes = {"blur", "skin"};
  m.metrics = {{"blur.ms", 1.0},
               {"skin.ms", 4.0},
               {"frame.ms", 5.0},
               {"skin.alu_ops", 2e6},
               {"skin.fragments_shaded", 1e5},
               {"blur.texture_samples", 1e6},
               {"blur.texture_miss_rate", 0.01},
               {"frame.dram_bytes", 2e7},
               {"skin.dram_bytes", 1.5e7},
               {"blur.dram_bytes", 5e6},
               {"quality.ssim_skin", 0.995}};
  m.pass_facts["blur"] = {"texture", 0.9, 0.2};
  m.pass_facts["skin"] = {"alu", 0.97, 0.8};
  return m;
}

Budget budget_of(const std::vector<std::pair<std::string, std::string>>& limits) {
  Budget b;
  b.name = "b";
  int line = 10;
  for (const auto& [metric, text] : limits) {
    b.limits.push_back(parse_limit(metric, text, line++, "t"));
  }
  return b;
}

TEST(Evaluate, AbsoluteLimitsPassAndFailWithMargins) {
  const Budget b = budget_of({{"skin.ms", "<= 4.5"},
                              {"skin.ms", "<= 3.5"},
                              {"quality.ssim_skin", ">= 0.99"},
                              {"quality.ssim_skin", ">= 0.999"},
                              {"skin.ms", "<= 4.0"}});
  const auto r = evaluate_budget("f.toml", b, synthetic(), nullptr);
  ASSERT_EQ(r.size(), 5u);
  EXPECT_TRUE(r[0].passed);
  EXPECT_DOUBLE_EQ(r[0].margin, 0.5);
  EXPECT_FALSE(r[1].passed);
  EXPECT_DOUBLE_EQ(r[1].margin, -0.5);
  EXPECT_TRUE(r[2].passed);
  EXPECT_NEAR(r[2].margin, 0.005, 1e-12);
  EXPECT_FALSE(r[3].passed);
  EXPECT_TRUE(r[4].passed) << "the bound itself is within the limit";
  EXPECT_TRUE(r[0].message.empty());
  EXPECT_FALSE(r[1].message.empty());
}

TEST(Evaluate, BaselineRelativeLimits) {
  BaselineEntry base;
  base.metrics = {{"skin.ms", 3.7},
                  {"frame.ms", 4.5},
                  {"quality.ssim_skin", 0.996},
                  {"skin.alu_ops", 1.5e6},
                  {"skin.fragments_shaded", 1e5},
                  {"blur.ms", 1.0}};
  const Budget b = budget_of({{"skin.ms", "<= baseline * 1.10"},
                              {"skin.ms", "<= baseline * 1.05"},
                              {"quality.ssim_skin", ">= baseline - 0.002"}});
  const auto r = evaluate_budget("f.toml", b, synthetic(), &base);
  EXPECT_TRUE(r[0].passed);
  EXPECT_DOUBLE_EQ(*r[0].baseline, 3.7);
  EXPECT_NEAR(r[0].bound, 4.07, 1e-12);
  EXPECT_FALSE(r[1].passed);
  EXPECT_NEAR(r[1].bound, 3.885, 1e-12);
  EXPECT_TRUE(r[2].passed);
  // The message says what moved, by how much, against which tolerance, and why.
  const std::string& m = r[1].message;
  EXPECT_NE(m.find("skin.ms rose from 3.700 ms to 4.000 ms (+8.1%, tolerance +5%"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("the skin pass is alu-bound (97% busy)"), std::string::npos) << m;
  EXPECT_NE(m.find("ALU ops 1500000 -> 2000000 (+33.3%)"), std::string::npos) << m;
  EXPECT_NE(m.find("fragments shaded 100000, unchanged"), std::string::npos) << m;
  EXPECT_NE(m.find("inside the 16.67 ms of 60 fps"), std::string::npos) << m;
}

TEST(Evaluate, FrameFailureNamesThePassThatMoved) {
  BaselineEntry base;
  base.metrics = {
      {"frame.ms", 4.2}, {"skin.ms", 3.2}, {"blur.ms", 1.0}, {"blur.texture_samples", 1e6}};
  Budget b = budget_of({{"frame.ms", "<= baseline * 1.05"}});
  b.target_fps = 250.0;  // 4 ms: the frame now misses it
  const auto r = evaluate_budget("f.toml", b, synthetic(), &base);
  ASSERT_FALSE(r[0].passed);
  const std::string& m = r[0].message;
  EXPECT_NE(m.find("most of the change is the skin pass (+0.800 ms)"), std::string::npos) << m;
  EXPECT_NE(m.find("misses 250 fps"), std::string::npos) << m;
}

TEST(Evaluate, CostBelowItsLowerLimitFailsAsMissingWork) {
  BaselineEntry base;  // every cost higher than the synthetic frame's: work went missing
  base.metrics = {{"frame.ms", 6.0}, {"frame.dram_bytes", 3e7}, {"skin.fragments_shaded", 2e5}};
  const Budget b = budget_of({{"frame.ms", ">= baseline * 0.95"},
                              {"frame.dram_bytes", ">= baseline * 0.95"},
                              {"skin.fragments_shaded", ">= baseline * 0.95"},
                              {"frame.ms", "<= baseline * 1.05"}});
  const auto r = evaluate_budget("f.toml", b, synthetic(), &base);
  for (int i = 0; i < 3; ++i) {
    ASSERT_FALSE(r[i].passed) << b.limits[i].metric;
    EXPECT_NE(r[i].message.find("dropped unexpectedly: did work go missing?"), std::string::npos)
        << r[i].message;
  }
  EXPECT_NE(r[0].message.find("frame.ms fell from 6.000 ms to 5.000 ms (-16.7%"), std::string::npos)
      << r[0].message;
  EXPECT_TRUE(r[3].passed) << "the upper limit alone cannot catch a drop";
}

TEST(Evaluate, TextureBoundPassExplainsWithSamplesAndMissRate) {
  const Budget b = budget_of({{"blur.ms", "<= 0.5"}});
  const auto r = evaluate_budget("f.toml", b, synthetic(), nullptr);
  EXPECT_NE(r[0].message.find("texture-bound"), std::string::npos);
  EXPECT_NE(r[0].message.find("miss rate 0.0100"), std::string::npos) << r[0].message;
}

TEST(Evaluate, UnknownPassIsBadInputNamingTheLine) {
  const Budget b = budget_of({{"skin.ms", "<= 9"}, {"sss.ms", "<= 1"}});
  try {
    evaluate_budget("f.toml", b, synthetic(), nullptr);
    FAIL();
  } catch (const BudgetError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("f.toml:11: budget 'b', limit 'sss.ms'"), std::string::npos) << what;
    EXPECT_NE(what.find("no pass 'sss' (its passes: blur, skin)"), std::string::npos) << what;
  }
}

TEST(Evaluate, RelativeLimitWithoutBaselineIsBadInput) {
  const Budget b = budget_of({{"skin.ms", "<= baseline * 1.05"}});
  EXPECT_THROW(evaluate_budget("f.toml", b, synthetic(), nullptr), BudgetError);
  BaselineEntry without_metric;
  without_metric.metrics = {{"frame.ms", 5.0}};
  try {
    evaluate_budget("f.toml", b, synthetic(), &without_metric);
    FAIL();
  } catch (const BudgetError& e) {
    EXPECT_NE(std::string(e.what()).find("baseline has no value"), std::string::npos);
  }
}

TEST(CheckTable, ListsEveryLimitAndTheFailures) {
  const Budget b = budget_of({{"skin.ms", "<= 4.5"}, {"frame.dram_bytes", "<= 1e7"}});
  CheckReport report;
  report.budgets.push_back({"b", "ipad4", evaluate_budget("f.toml", b, synthetic(), nullptr), 0.0});
  const std::string table = format_check_table(report);
  EXPECT_NE(table.find("budget"), std::string::npos);
  EXPECT_NE(table.find("+0.500 ms (+11.1%)  pass"), std::string::npos) << table;
  EXPECT_NE(table.find("-10.000 MB (-100.0%)  FAIL"), std::string::npos) << table;
  EXPECT_NE(table.find("FAIL b / frame.dram_bytes: frame.dram_bytes is 20.000 MB"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("1 of 2 limits in 1 budgets passed, 1 failed"), std::string::npos);
  // Points at the run-to-run diff, and says why it cannot name the runs itself.
  EXPECT_NE(table.find("`skinsim compare base new`"), std::string::npos) << table;
  EXPECT_NE(table.find("keeps no run directories"), std::string::npos) << table;
}

}  // namespace
}  // namespace skinsim::budget
