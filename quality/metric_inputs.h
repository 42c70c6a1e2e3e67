// Shared input checks and masked reductions of the metrics.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>
#include <numeric>
#include <string_view>
#include <vector>

#include "image/image.h"

namespace skinsim::quality {

// Throws QualityError naming the metric and the problem: empty or mismatched sizes, a pixel
// array that does not match width x height, a mask of another size or selecting no pixel, or
// a NaN/infinite value.
void check_metric_inputs(std::string_view metric, const image::Image& test,
                         const image::Image& reference, const image::Mask* mask);

// Mean of `values` (width x height) over the mask (all pixels without one). Rows are summed in
// parallel and the row sums added in row order, so the result does not depend on threads.
template <typename T>
double masked_mean(const std::vector<T>& values, int width, int height, const image::Mask* mask) {
  std::vector<double> row_sums(height, 0.0);
  std::vector<std::size_t> row_counts(height, 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      const std::size_t begin = static_cast<std::size_t>(y) * width;
      double sum = 0.0;
      std::size_t count = 0;
      for (std::size_t i = begin; i < begin + width; ++i) {
        if (mask != nullptr && mask->values[i] == 0) continue;
        sum += static_cast<double>(values[i]);
        ++count;
      }
      row_sums[y] = sum;
      row_counts[y] = count;
    }
  });
  const double total = std::accumulate(row_sums.begin(), row_sums.end(), 0.0);
  const std::size_t count = std::accumulate(row_counts.begin(), row_counts.end(), std::size_t{0});
  return total / static_cast<double>(count);
}

}  // namespace skinsim::quality
