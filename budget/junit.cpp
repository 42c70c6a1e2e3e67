#include "budget/junit.h"

#include <fmt/format.h>

#include "budget/value_format.h"
#include "util/text.h"

namespace skinsim::budget {

std::string junit_xml(const CheckReport& report, const std::string& suite_name) {
  double total_seconds = 0.0;
  for (const BudgetOutcome& b : report.budgets) total_seconds += b.seconds;
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += fmt::format(
      "<testsuites name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{:.3f}\">\n",
      escape_markup(suite_name), report.limit_count(), report.failure_count(), total_seconds);
  for (const BudgetOutcome& b : report.budgets) {
    int failures = 0;
    for (const LimitResult& r : b.limits) failures += r.passed ? 0 : 1;
    out += fmt::format(
        "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{:.3f}\">\n",
        escape_markup(b.name), b.limits.size(), failures, b.seconds);
    for (const LimitResult& r : b.limits) {
      const std::string name = fmt::format("{} {}", r.limit.metric, r.limit.text);
      out += fmt::format("    <testcase classname=\"{}\" name=\"{}\">", escape_markup(b.name),
                         escape_markup(name));
      const std::string measured =
          fmt::format("measured {}, bound {}", format_value(r.limit.metric, r.measured),
                      format_value(r.limit.metric, r.bound));
      if (r.passed) {
        out += fmt::format("<system-out>{}</system-out></testcase>\n", escape_markup(measured));
      } else {
        out += fmt::format(
            "\n      <failure message=\"{}\" type=\"budget exceeded\">{}</failure>\n    "
            "</testcase>\n",
            escape_markup(r.message), escape_markup(measured));
      }
    }
    out += "  </testsuite>\n";
  }
  out += "</testsuites>\n";
  return out;
}

}  // namespace skinsim::budget
