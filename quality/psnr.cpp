#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include <vector>

#include "quality/metric_inputs.h"
#include "quality/metrics.h"

namespace skinsim::quality {

double psnr(const image::Image& test, const image::Image& reference, const image::Mask* mask) {
  check_metric_inputs("PSNR", test, reference, mask);
  // Per-pixel squared error averaged over R, G, B, in double so that a uniform offset d gives
  // exactly -20 log10(d) up to rounding.
  std::vector<double> squared_error(test.pixel_count());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, squared_error.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i < range.end(); ++i) {
                        double sum = 0.0;
                        for (int c = 0; c < 3; ++c) {
                          const double d = static_cast<double>(test.rgb[i][c]) -
                                           static_cast<double>(reference.rgb[i][c]);
                          sum += d * d;
                        }
                        squared_error[i] = sum / 3.0;
                      }
                    });
  const double mse = masked_mean(squared_error, test.width, test.height, mask);
  if (mse == 0.0) return std::numeric_limits<double>::infinity();
  return -10.0 * std::log10(mse);  // peak value 1.0
}

}  // namespace skinsim::quality
