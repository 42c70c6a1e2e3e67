#include "budget/value_format.h"

#include <fmt/format.h>

#include <cmath>

#include "budget/metrics.h"

namespace skinsim::budget {

namespace {

std::string format_magnitude(const std::string& metric, double v, bool sign) {
  const std::string kind = metric_kind(metric);
  const std::string s = sign ? "+" : "";
  if (std::isinf(v)) return v > 0 ? s + "inf" : "-inf";
  if (kind == "ms") return fmt::format(fmt::runtime("{:" + s + ".3f} ms"), v);
  if (kind == "dram_bytes") return fmt::format(fmt::runtime("{:" + s + ".3f} MB"), v / 1e6);
  if (kind == "energy_mj") return fmt::format(fmt::runtime("{:" + s + ".3f} mJ"), v);
  if (kind == "texture_miss_rate") return fmt::format(fmt::runtime("{:" + s + ".4f}"), v);
  if (kind.starts_with("psnr")) return fmt::format(fmt::runtime("{:" + s + ".2f} dB"), v);
  if (kind.starts_with("ssim") || kind.starts_with("flip")) {
    return fmt::format(fmt::runtime("{:" + s + ".4f}"), v);
  }
  return fmt::format(fmt::runtime("{:" + s + ".0f}"), v);  // counts
}

}  // namespace

std::string format_value(const std::string& metric, double value) {
  return format_magnitude(metric, value, false);
}

std::string format_delta(const std::string& metric, double delta) {
  return format_magnitude(metric, delta, true);
}

std::string format_change(double from, double to) {
  if (from == 0.0 || !std::isfinite(from) || !std::isfinite(to)) return "n/a";
  return fmt::format("{:+.1f}%", (to - from) / std::fabs(from) * 100.0);
}

}  // namespace skinsim::budget
