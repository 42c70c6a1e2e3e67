#include "budget/check_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "budget/value_format.h"

namespace skinsim::budget {

namespace {

using Row = std::array<std::string, 6>;

// `skinsim check` renders in memory and keeps no run directories, so there is none to name.
constexpr const char* kCompareHint =
    "\nTo see every counter, time and pixel that moved: `skinsim check` keeps no run "
    "directories, so render the failing budget's frame (its device, resolution and knobs) with "
    "`skinsim run --out base` at the baseline's skinsim version and `skinsim run --out new` "
    "now, then run `skinsim compare base new` (docs/reports.md).\n";

std::string limit_cell(const LimitResult& r) {
  const std::string bound = format_value(r.limit.metric, r.bound);
  if (!r.limit.uses_baseline())
    return fmt::format("{} {}", comparison_text(r.limit.comparison), bound);
  return fmt::format("{} {} ({})", comparison_text(r.limit.comparison), bound,
                     r.limit.bound_text());
}

std::string margin_cell(const LimitResult& r) {
  std::string text = format_delta(r.limit.metric, r.margin);
  if (r.bound != 0.0 && std::isfinite(r.bound) && std::isfinite(r.margin)) {
    text += fmt::format(" ({:+.1f}%)", r.margin / std::fabs(r.bound) * 100.0);
  }
  return text;
}

}  // namespace

std::string format_check_table(const CheckReport& report) {
  std::vector<Row> rows = {{"budget", "metric", "limit", "measured", "margin", "result"}};
  for (const BudgetOutcome& b : report.budgets) {
    for (const LimitResult& r : b.limits) {
      rows.push_back({b.name, r.limit.metric, limit_cell(r),
                      format_value(r.limit.metric, r.measured), margin_cell(r),
                      r.passed ? "pass" : "FAIL"});
    }
  }
  std::array<std::size_t, 6> width{};
  for (const Row& row : rows) {
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  }
  std::string out;
  for (const Row& row : rows) {
    std::string line;
    for (std::size_t c = 0; c < row.size(); ++c) {
      // Text columns left-aligned, numbers right-aligned.
      line += c == 0 || c == 1 || c == 2 || c == 5 ? fmt::format("{:<{}}", row[c], width[c])
                                                   : fmt::format("{:>{}}", row[c], width[c]);
      line += c + 1 < row.size() ? "  " : "";
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += line + "\n";
  }
  for (const BudgetOutcome& b : report.budgets) {
    for (const LimitResult& r : b.limits) {
      if (!r.passed) out += fmt::format("\nFAIL {} / {}: {}\n", b.name, r.limit.metric, r.message);
    }
  }
  if (!report.passed()) out += kCompareHint;
  out += fmt::format("\n{} of {} limits in {} budgets passed{}\n",
                     report.limit_count() - report.failure_count(), report.limit_count(),
                     report.budgets.size(),
                     report.passed() ? "" : fmt::format(", {} failed", report.failure_count()));
  return out;
}

}  // namespace skinsim::budget
