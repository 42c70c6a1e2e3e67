// Strict number parsing for every number a user types: CLI options, pipeline knobs, sweep files
// and budgets. Only plain decimal integers ("-12") and decimal or scientific reals ("0.5",
// "1e-3") are accepted: no hex ("0x10"), no surrounding spaces, no "+", "nan" or "inf", so a
// typo is an error instead of a silently different value.
#pragma once

#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>
#include <system_error>

namespace skinsim {

// The integer `text` spells, or nullopt when it is not a plain decimal integer of type T
// (including when it does not fit T).
template <typename T = long long>
std::optional<T> parse_integer(std::string_view text) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value, 10);
  if (text.empty() || ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

// The finite real `text` spells, or nullopt when it is not a decimal/scientific number or its
// value does not fit T finitely (1e308 as a float, 1e999 as a double).
template <typename T = double>
std::optional<T> parse_real(std::string_view text) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value, std::chars_format::general);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

}  // namespace skinsim
