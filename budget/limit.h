// One limit of a budget: `"<metric>" = "<op> <bound>"` where op is <= or >= and the bound is
// a number, or relative to the stored baseline: `baseline`, `baseline * F`, `baseline + D`
// or `baseline - D` (see docs/budgets.md).
#pragma once

#include <string>

namespace skinsim::budget {

enum class Comparison { kAtMost, kAtLeast };  // <=, >=
enum class BaselineOp { kNone, kScale, kOffset };

struct Limit {
  std::string metric;  // e.g. "skin.ms"
  std::string text;    // the limit as written, e.g. "<= baseline * 1.05"
  int line = 0;        // in the budget file
  Comparison comparison = Comparison::kAtMost;
  // kNone: `value` is the absolute bound. kScale: bound = baseline * value.
  // kOffset: bound = baseline + value.
  BaselineOp relative = BaselineOp::kNone;
  double value = 0.0;

  bool uses_baseline() const { return relative != BaselineOp::kNone; }
  // The bound given the baseline's value of the metric (ignored for absolute limits).
  double bound(double baseline) const;
  // The bound as written, normalised: "16", "baseline * 1.05", "baseline - 0.5".
  std::string bound_text() const;
  // The tolerance in words, e.g. "5%" for `baseline * 1.05`, "0.5" for `baseline - 0.5`.
  std::string tolerance_text() const;
};

// Parses the right-hand side of a limit; throws BudgetError starting with `where` (e.g.
// "budgets.toml:12: limit 'skin.ms'") on bad syntax.
Limit parse_limit(const std::string& metric, const std::string& text, int line,
                  const std::string& where);

const char* comparison_text(Comparison c);

}  // namespace skinsim::budget
