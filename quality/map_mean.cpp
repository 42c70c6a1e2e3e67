#include "quality/metric_inputs.h"
#include "quality/metrics.h"

namespace skinsim::quality {

double map_mean(const image::ScalarMap& map, const image::Mask* mask) {
  return masked_mean(map.values, map.width, map.height, mask);
}

}  // namespace skinsim::quality
