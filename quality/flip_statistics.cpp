#include <algorithm>
#include <cmath>

#include "quality/error.h"
#include "quality/metric_inputs.h"
#include "quality/metrics.h"

namespace skinsim::quality {

namespace {

// Nearest-rank percentile of sorted values (q in [0, 1]).
double percentile(const std::vector<float>& sorted, double q) {
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
  return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

}  // namespace

double FlipStatistics::visible_percent() const {
  return pixels == 0 ? 0.0 : 100.0 * static_cast<double>(visible_pixels) / pixels;
}

bool FlipStatistics::visible(const FlipParams& params) const {
  return static_cast<double>(visible_pixels) >= flip_visible_area_pixels(params);
}

FlipStatistics flip_statistics(const ScalarMap& map, const Mask* mask) {
  if (mask && (mask->width != map.width || mask->height != map.height)) {
    throw QualityError("FLIP statistics: mask and map sizes differ");
  }
  std::vector<float> values;
  values.reserve(mask ? mask->count() : map.values.size());
  for (std::size_t i = 0; i < map.values.size(); ++i) {
    if (!mask || mask->values[i] != 0) values.push_back(map.values[i]);
  }
  FlipStatistics s;
  s.pixels = values.size();
  if (values.empty()) return s;
  const float threshold = static_cast<float>(flip_visibility_threshold());
  for (const float v : values) s.visible_pixels += v > threshold ? 1 : 0;
  s.mean = masked_mean(map.values, map.width, map.height, mask);  // as FlipResult::mean
  std::sort(values.begin(), values.end());
  s.p95 = percentile(values, 0.95);
  s.p99 = percentile(values, 0.99);
  return s;
}

}  // namespace skinsim::quality
