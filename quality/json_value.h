// How metric values go into JSON: JSON has no infinity, and PSNR of identical images is
// +infinity, so non-finite values are written as the strings "inf", "-inf" or "nan"
// (nlohmann::json would silently write null). See docs/quality-metrics.md.
#pragma once

#include <cmath>
#include <nlohmann/json.hpp>

namespace skinsim::quality {

inline nlohmann::json metric_to_json(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

// Inverse of metric_to_json; throws nlohmann::json::type_error for other strings or types.
inline double metric_from_json(const nlohmann::json& value) {
  if (value.is_string()) {
    const auto& text = value.get_ref<const std::string&>();
    if (text == "inf") return HUGE_VAL;
    if (text == "-inf") return -HUGE_VAL;
    if (text == "nan") return std::nan("");
    throw nlohmann::json::type_error::create(
        302, "metric string must be inf, -inf or nan, got '" + text + "'", &value);
  }
  return value.get<double>();
}

}  // namespace skinsim::quality
