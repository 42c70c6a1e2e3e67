#include "budget/junit.h"

#include <fmt/format.h>

#include "budget/value_format.h"

namespace skinsim::budget {

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      case '\n':
        out += "&#10;";  // kept inside attribute values too
        break;
      default:
        const auto u = static_cast<unsigned char>(c);
        out += (u < 0x20 && c != '\t' && c != '\r') ? '?' : c;
    }
  }
  return out;
}

std::string junit_xml(const CheckReport& report, const std::string& suite_name) {
  double total_seconds = 0.0;
  for (const BudgetOutcome& b : report.budgets) total_seconds += b.seconds;
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += fmt::format(
      "<testsuites name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{:.3f}\">\n",
      xml_escape(suite_name), report.limit_count(), report.failure_count(), total_seconds);
  for (const BudgetOutcome& b : report.budgets) {
    int failures = 0;
    for (const LimitResult& r : b.limits) failures += r.passed ? 0 : 1;
    out += fmt::format(
        "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{:.3f}\">\n",
        xml_escape(b.name), b.limits.size(), failures, b.seconds);
    for (const LimitResult& r : b.limits) {
      const std::string name = fmt::format("{} {}", r.limit.metric, r.limit.text);
      out += fmt::format("    <testcase classname=\"{}\" name=\"{}\">", xml_escape(b.name),
                         xml_escape(name));
      const std::string measured =
          fmt::format("measured {}, bound {}", format_value(r.limit.metric, r.measured),
                      format_value(r.limit.metric, r.bound));
      if (r.passed) {
        out += fmt::format("<system-out>{}</system-out></testcase>\n", xml_escape(measured));
      } else {
        out += fmt::format(
            "\n      <failure message=\"{}\" type=\"budget exceeded\">{}</failure>\n    "
            "</testcase>\n",
            xml_escape(r.message), xml_escape(measured));
      }
    }
    out += "  </testsuite>\n";
  }
  out += "</testsuites>\n";
  return out;
}

}  // namespace skinsim::budget
