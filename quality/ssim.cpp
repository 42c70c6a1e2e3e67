#include <span>
#include <vector>

#include "quality/metric_inputs.h"
#include "quality/metrics.h"
#include "quality/separable_stream.h"

namespace skinsim::quality {
namespace {

// Wang et al. 2004, section III-C: K1 = 0.01, K2 = 0.03, dynamic range L = 1, and an 11x11
// circular-symmetric Gaussian weighting window with standard deviation 1.5 (normalised).
constexpr double kK1 = 0.01;
constexpr double kK2 = 0.03;
constexpr double kL = 1.0;
constexpr double kWindowSigma = 1.5;
constexpr int kWindowRadius = 5;

float luma(const glm::vec3& p) {
  return 0.299f * p.r + 0.587f * p.g + 0.114f * p.b;
}  // BT.601

}  // namespace

double ssim(const image::Image& test, const image::Image& reference, const image::Mask* mask,
            image::ScalarMap* map) {
  check_metric_inputs("SSIM", test, reference, mask);
  const std::vector<float> window = gaussian_kernel(kWindowSigma, kWindowRadius);
  // Source channels: x, y, x^2, y^2, xy; each is averaged by the window along x, then y.
  SeparableStream stream{test.width, test.height, 5, {}, {}, {}};
  for (int c = 0; c < 5; ++c) {
    stream.row_filters.push_back({c, window});
    stream.column_filters.push_back({c, window});
  }
  const auto source = [&](int y, Columns columns, std::span<float* const> rows) {
    const std::size_t begin = static_cast<std::size_t>(y) * test.width;
    for (int x = columns.begin; x < columns.end; ++x) {
      const float a = luma(test.rgb[begin + x]);
      const float b = luma(reference.rgb[begin + x]);
      rows[0][x] = a;
      rows[1][x] = b;
      rows[2][x] = a * a;
      rows[3][x] = b * b;
      rows[4][x] = a * b;
    }
  };
  const double c1 = (kK1 * kL) * (kK1 * kL);
  const double c2 = (kK2 * kL) * (kK2 * kL);
  std::vector<float> values(test.pixel_count());
  const auto sink = [&](int y, Columns columns, std::span<const float* const> mean) {
    float* out = &values[static_cast<std::size_t>(y) * test.width];
    for (int x = columns.begin; x < columns.end; ++x) {
      const double mx = mean[0][x];
      const double my = mean[1][x];
      const double var_x = mean[2][x] - mx * mx;
      const double var_y = mean[3][x] - my * my;
      const double cov = mean[4][x] - mx * my;
      // Wang et al. 2004, eq. 13.
      out[x] = static_cast<float>(((2.0 * mx * my + c1) * (2.0 * cov + c2)) /
                                  ((mx * mx + my * my + c1) * (var_x + var_y + c2)));
    }
  };
  run_separable_stream(stream, source, sink);
  const double mean = masked_mean(values, test.width, test.height, mask);
  if (map != nullptr) *map = image::ScalarMap{test.width, test.height, std::move(values)};
  return mean;
}

}  // namespace skinsim::quality
