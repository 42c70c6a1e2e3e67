#include "budget/limit.h"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>

#include "budget/error.h"

namespace skinsim::budget {

namespace {

// A tiny cursor over the limit text: whitespace-separated tokens of <=, >=, numbers, the word
// `baseline` and the operators * + -.
class Cursor {
 public:
  explicit Cursor(const std::string& text) : text_(text) {}
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool done() {
    skip_space();
    return pos_ == text_.size();
  }
  bool take(std::string_view token) {
    skip_space();
    if (text_.compare(pos_, token.size(), token) != 0) return false;
    pos_ += token.size();
    return true;
  }
  std::optional<double> number() {
    skip_space();
    const char* begin = text_.data() + pos_;
    const char* end = text_.data() + text_.size();
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec != std::errc() || !std::isfinite(value)) return std::nullopt;
    pos_ += static_cast<std::size_t>(ptr - begin);
    return value;
  }

 private:
  const std::string& text_;
  std::size_t pos_ = 0;
};

}  // namespace

double Limit::bound(double baseline) const {
  switch (relative) {
    case BaselineOp::kNone:
      return value;
    case BaselineOp::kScale:
      return baseline * value;
    case BaselineOp::kOffset:
      return baseline + value;
  }
  return value;
}

std::string Limit::tolerance_text() const {
  switch (relative) {
    case BaselineOp::kNone:
      return "absolute";
    case BaselineOp::kScale:
      return fmt::format("{:+.4g}%", (value - 1.0) * 100.0);
    case BaselineOp::kOffset:
      return fmt::format("{:+.4g}", value);
  }
  return "absolute";
}

std::string Limit::bound_text() const {
  switch (relative) {
    case BaselineOp::kNone:
      return fmt::format("{:g}", value);
    case BaselineOp::kScale:
      return fmt::format("baseline * {:g}", value);
    case BaselineOp::kOffset:
      return fmt::format("baseline {} {:g}", value < 0.0 ? '-' : '+', std::fabs(value));
  }
  return {};
}

const char* comparison_text(Comparison c) {
  return c == Comparison::kAtMost ? "<=" : ">=";
}

Limit parse_limit(const std::string& metric, const std::string& text, int line,
                  const std::string& where) {
  const auto fail = [&](const std::string& why) {
    return BudgetError(fmt::format(
        "{}: {} in \"{}\" (expected \"<= 16.0\", \">= 0.99\", \"<= baseline * 1.05\" or "
        "\">= baseline - 0.5\")",
        where, why, text));
  };
  Limit limit;
  limit.metric = metric;
  limit.text = text;
  limit.line = line;
  Cursor c(text);
  if (c.take("<=")) {
    limit.comparison = Comparison::kAtMost;
  } else if (c.take(">=")) {
    limit.comparison = Comparison::kAtLeast;
  } else {
    throw fail("the limit must start with <= or >=");
  }
  if (c.take("baseline")) {
    if (c.done()) {
      limit.relative = BaselineOp::kScale;
      limit.value = 1.0;
      return limit;
    }
    double sign = 1.0;
    if (c.take("*")) {
      limit.relative = BaselineOp::kScale;
    } else if (c.take("+")) {
      limit.relative = BaselineOp::kOffset;
    } else if (c.take("-")) {
      limit.relative = BaselineOp::kOffset;
      sign = -1.0;
    } else {
      throw fail("after 'baseline' expected * F, + D or - D");
    }
    const std::optional<double> v = c.number();
    if (!v) throw fail("expected a number after the operator");
    if (limit.relative == BaselineOp::kScale && *v <= 0.0) {
      throw fail("the baseline factor must be positive");
    }
    if (limit.relative == BaselineOp::kOffset && *v < 0.0) {
      throw fail("write a negative offset as 'baseline - D'");
    }
    limit.value = sign * *v;
  } else {
    const std::optional<double> v = c.number();
    if (!v) throw fail("expected a number or 'baseline' after the comparison");
    limit.value = *v;
  }
  if (!c.done()) throw fail("unexpected text after the bound");
  return limit;
}

}  // namespace skinsim::budget
