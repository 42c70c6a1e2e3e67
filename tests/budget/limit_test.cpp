// Limit syntax: absolute and baseline-relative bounds, and every malformed form.
#include "budget/limit.h"

#include <gtest/gtest.h>

#include "budget/error.h"

namespace skinsim::budget {
namespace {

Limit parse(const std::string& text) {
  return parse_limit("skin.ms", text, 7, "f.toml:7");
}

TEST(Limit, AbsoluteBounds) {
  const Limit at_most = parse("<= 16.0");
  EXPECT_EQ(at_most.comparison, Comparison::kAtMost);
  EXPECT_FALSE(at_most.uses_baseline());
  EXPECT_DOUBLE_EQ(at_most.bound(123.0), 16.0);
  const Limit at_least = parse(">=0.99");
  EXPECT_EQ(at_least.comparison, Comparison::kAtLeast);
  EXPECT_DOUBLE_EQ(at_least.bound(0.0), 0.99);
  EXPECT_DOUBLE_EQ(parse("<= 3e7").value, 3e7);
  EXPECT_EQ(parse("<= 16.0").line, 7);
}

TEST(Limit, BaselineRelativeBounds) {
  const Limit scaled = parse("<= baseline * 1.05");
  EXPECT_TRUE(scaled.uses_baseline());
  EXPECT_DOUBLE_EQ(scaled.bound(10.0), 10.5);
  EXPECT_EQ(scaled.tolerance_text(), "+5%");
  EXPECT_EQ(scaled.bound_text(), "baseline * 1.05");
  const Limit minus = parse(">= baseline - 0.5");
  EXPECT_DOUBLE_EQ(minus.bound(38.0), 37.5);
  EXPECT_EQ(minus.bound_text(), "baseline - 0.5");
  EXPECT_DOUBLE_EQ(parse("<= baseline + 0.01").bound(0.02), 0.03);
  EXPECT_DOUBLE_EQ(parse("<= baseline").bound(4.0), 4.0);
}

TEST(Limit, MalformedLimitsNameWhereAndWhat) {
  for (const char* bad :
       {"16.0", "< 16", "<= ", "<= fast", "<= baseline * ", "<= baseline / 2", "<= baseline * 0",
        "<= baseline * -1", "<= baseline + -1", "<= 16 ms", "<= nan", "<= inf", "== 3"}) {
    try {
      parse(bad);
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const BudgetError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("f.toml:7", 0), 0u) << what;
      EXPECT_NE(what.find(bad), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace skinsim::budget
