#include "crosscheck/target_compare.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace skinsim::crosscheck {

nlohmann::json compare_targets(const std::vector<float>& emulated,
                               const std::vector<float>& replayed, int width, int height,
                               bool depth) {
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  const int channels = depth ? 1 : 4;
  float peak = 1.0f;
  for (std::size_t i = 0; i < pixels * 4; ++i) peak = std::max(peak, std::fabs(emulated[i]));
  // Half a step past one 8-bit level: what separates a real difference from rounding.
  const double differing_above = depth ? 1e-4 : 1.5 / 255.0 * peak;
  double squared = 0.0, max_abs = 0.0;
  std::size_t differing = 0;
  for (std::size_t p = 0; p < pixels; ++p) {
    double largest = 0.0;
    for (int c = 0; c < channels; ++c) {
      const double d = std::fabs(static_cast<double>(emulated[p * 4 + c]) - replayed[p * 4 + c]);
      squared += d * d;
      largest = std::max(largest, d);
    }
    max_abs = std::max(max_abs, largest);
    if (largest > differing_above) ++differing;
  }
  const double mse = squared / static_cast<double>(pixels * channels);
  const double psnr = mse == 0.0 ? std::numeric_limits<double>::infinity()
                                 : 10.0 * std::log10(static_cast<double>(peak) * peak / mse);
  return {{"psnr_db", std::isinf(psnr) ? nlohmann::json("inf") : nlohmann::json(psnr)},
          {"peak", peak},
          {"max_abs", max_abs},
          {"differing_above", differing_above},
          {"differing_fraction", static_cast<double>(differing) / static_cast<double>(pixels)},
          {"pixels", pixels},
          {"depth", depth}};
}

std::string format_row(const nlohmann::json& r) {
  const std::string psnr = r["psnr_db"].is_string()
                               ? std::string("identical")
                               : fmt::format("{:.2f} dB", r["psnr_db"].get<double>());
  return fmt::format("  {:<24} PSNR {:>10}  max |diff| {:.4f}  differing {:.3f}% of {} px{}",
                     r["pass"].get<std::string>(), psnr, r["max_abs"].get<double>(),
                     100.0 * r["differing_fraction"].get<double>(), r["pixels"].get<std::size_t>(),
                     r["depth"].get<bool>() ? " (depth)" : "");
}

}  // namespace skinsim::crosscheck
