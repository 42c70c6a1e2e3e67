// Budgets on a sequence (`sequence = "push-in"`): limits on the frame-time distribution
// (frame_ms.p95, frame_ms.max), a budget failing on its p95 frame time, and what a budget file
// may not ask of a sequence.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "budget/budget_file.h"
#include "budget/error.h"
#include "budget/evaluate.h"
#include "budget/run_budget.h"
#include "tests/test_paths.h"

namespace skinsim::budget {
namespace {

// The budget with `limits` (TOML lines) on a short push-in of a small head.
std::string push_in_budget(const std::string& limits) {
  return R"(
[[budget]]
name = "push"
device = "ipad4"
resolution = "96x72"
sequence = "push-in"
frames = 8
[budget.scene]
head_triangles = 4000
texture_size = 128
[budget.pipeline]
shadow_map_size = 256
[budget.limits]
)" + limits;
}

std::string load_error(const std::string& text) {
  try {
    parse_budget_file(text, "seq.toml");
  } catch (const BudgetError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SequenceBudget, FailsOnItsP95FrameTime) {
  const BudgetFile measured_file =
      parse_budget_file(push_in_budget("\"frame_ms.max\" = \"<= 1000\"\n"), "seq.toml");
  const Budget& measured = measured_file.budgets.at(0);
  ASSERT_TRUE(measured.sequence);
  EXPECT_EQ(measured.sequence->frames, 8);
  const Measurement m =
      run_budget("seq.toml", measured, test_paths::kDataDir, 2, false).measurement;
  const double p50 = m.metrics.at("frame_ms.p50");
  const double p95 = m.metrics.at("frame_ms.p95");
  const double max = m.metrics.at("frame_ms.max");
  ASSERT_LT(p50, p95);  // the close-up frames cost more than the far ones
  EXPECT_LE(p95, max);
  EXPECT_EQ(m.metrics.at("frame.ms"), max);  // the other metrics are the worst frame's

  // A bound between the median and the p95 frame time: the p95 limit fails, the max limit set
  // above the worst frame passes.
  const std::string bound = fmt::format("{:.6f}", (p50 + p95) / 2.0);
  const BudgetFile file = parse_budget_file(
      push_in_budget(fmt::format("\"frame_ms.p95\" = \"<= {}\"\n\"frame_ms.max\" = \"<= {:.6f}\"\n",
                                 bound, max * 1.01)),
      "seq.toml");
  const std::vector<LimitResult> results =
      evaluate_budget("seq.toml", file.budgets.at(0), m, nullptr);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0].limit.metric, "frame_ms.p95");
  EXPECT_FALSE(results[0].passed);
  EXPECT_NE(results[0].message.find("over push-in's 8 frames at 30 fps"), std::string::npos)
      << results[0].message;
  EXPECT_NE(results[0].message.find("at frame 7"), std::string::npos) << results[0].message;
  EXPECT_TRUE(results[1].passed);
}

TEST(SequenceBudget, BadSequenceBudgetsNameTheLine) {
  EXPECT_NE(load_error(push_in_budget("\"quality.ssim_skin\" = \">= 0.9\"\n"))
                .find("a sequence budget renders no reference"),
            std::string::npos);
  std::string no_sequence = push_in_budget("\"frame_ms.p95\" = \"<= 10\"\n");
  no_sequence.replace(no_sequence.find("sequence = \"push-in\"\nframes = 8\n"), 32, "");
  EXPECT_NE(load_error(no_sequence).find("limit 'frame_ms.p95': a frame-time distribution needs"),
            std::string::npos)
      << load_error(no_sequence);
  std::string nope = push_in_budget("\"frame_ms.p95\" = \"<= 10\"\n");
  nope.replace(nope.find("push-in"), 7, "nope");
  EXPECT_NE(load_error(nope).find("seq.toml:6: budget 'push'.sequence: --sequence: unknown "
                                  "sequence 'nope'"),
            std::string::npos)
      << load_error(nope);
  EXPECT_NE(load_error(push_in_budget("\"frame_ms.p90\" = \"<= 10\"\n")).find("no such metric"),
            std::string::npos);
  std::string zero = push_in_budget("\"frame_ms.p95\" = \"<= 10\"\n");
  zero.replace(zero.find("frames = 8"), 10, "frames = 0");
  EXPECT_NE(load_error(zero).find("budget 'push'.frames must be in [1, "), std::string::npos)
      << load_error(zero);
}

}  // namespace
}  // namespace skinsim::budget
