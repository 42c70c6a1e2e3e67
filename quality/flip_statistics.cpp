#include <algorithm>
#include <cmath>

#include "quality/error.h"
#include "quality/metric_inputs.h"
#include "quality/metrics.h"

namespace skinsim::quality {

namespace {

// Where the nearest-rank percentile q (in [0, 1]) of `count` values sits once they are sorted.
std::size_t rank_index(std::size_t count, double q) {
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(count)));
  return std::clamp<std::size_t>(rank, 1, count) - 1;
}

}  // namespace

double visible_percent(std::size_t visible, std::size_t pixels) {
  return pixels == 0 ? 0.0 : 100.0 * static_cast<double>(visible) / static_cast<double>(pixels);
}

double FlipStatistics::visible_percent() const {
  return quality::visible_percent(visible_pixels, pixels);
}

bool FlipStatistics::visible(const FlipParams& params) const {
  return static_cast<double>(visible_pixels) >= flip_visible_area_pixels(params);
}

namespace {

std::size_t count_visible(const std::vector<float>& values) {
  const float threshold = static_cast<float>(flip_visibility_threshold());
  std::size_t visible = 0;
  for (const float v : values) visible += v > threshold ? 1 : 0;
  return visible;
}

}  // namespace

std::size_t flip_visible_pixels(const image::ScalarMap& map) {
  return count_visible(map.values);
}

FlipStatistics flip_statistics(const image::ScalarMap& map, const image::Mask* mask) {
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
  s.visible_pixels = count_visible(values);
  s.mean = masked_mean(map.values, map.width, map.height, mask);  // as FlipResult::mean
  // The percentiles by selection, not a full sort (the same values in linear time): after the
  // first selection every value from p95's place on is at least p95, so p99's is among them.
  const std::size_t i95 = rank_index(values.size(), 0.95);
  const std::size_t i99 = rank_index(values.size(), 0.99);
  const auto at = [&](std::size_t i) { return values.begin() + static_cast<std::ptrdiff_t>(i); };
  std::nth_element(values.begin(), at(i95), values.end());
  s.p95 = values[i95];
  std::nth_element(at(i95), at(i99), values.end());
  s.p99 = values[i99];
  return s;
}

}  // namespace skinsim::quality
