#include "quality/metric_inputs.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <string>

#include "quality/error.h"
#include "util/float_lanes.h"

namespace skinsim::quality {
namespace {

std::string size_text(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

bool finite(const glm::vec3& p) {
  return std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b);
}

// Whether `count` floats are all finite, four at a time: a value is infinite or NaN exactly
// when its exponent bits are all ones.
bool all_finite(const float* values, std::size_t count) {
  const Int4 exponent = {0x7f800000, 0x7f800000, 0x7f800000, 0x7f800000};
  Int4 bad{};
  std::size_t j = 0;
  for (; j + 4 <= count; j += 4) {
    Int4 v;
    std::memcpy(&v, values + j, sizeof v);
    bad |= (v & exponent) == exponent;
  }
  bool finite_so_far = (bad[0] | bad[1] | bad[2] | bad[3]) == 0;
  for (; j < count; ++j) finite_so_far = finite_so_far && std::isfinite(values[j]);
  return finite_so_far;
}

void check_image(std::string_view metric, std::string_view role, const image::Image& image) {
  const std::string where = std::string(metric) + ": " + std::string(role) + " image";
  if (image.width <= 0 || image.height <= 0) {
    throw QualityError(where + " is empty (" + size_text(image.width, image.height) + ")");
  }
  if (image.rgb.size() != image.pixel_count()) {
    throw QualityError(where + " holds " + std::to_string(image.rgb.size()) +
                       " pixels but is declared " + size_text(image.width, image.height));
  }
  // Every metric checks both its images: on every thread, a block's pixels looked at one by
  // one only when the block holds a non-finite value.
  std::atomic<std::size_t> first_bad = image.rgb.size();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, image.rgb.size(), std::size_t{1} << 16),
                    [&](const tbb::blocked_range<std::size_t>& pixels) {
                      if (all_finite(&image.rgb[pixels.begin()].x, 3 * pixels.size())) return;
                      std::size_t i = pixels.begin();
                      while (finite(image.rgb[i])) ++i;
                      std::size_t seen = first_bad.load();
                      while (i < seen && !first_bad.compare_exchange_weak(seen, i)) {
                      }
                    });
  if (const std::size_t i = first_bad.load(); i < image.rgb.size()) {
    throw QualityError(where + " has a non-finite value at pixel (" +
                       std::to_string(i % image.width) + ", " + std::to_string(i / image.width) +
                       ")");
  }
}

}  // namespace

void check_metric_inputs(std::string_view metric, const image::Image& test,
                         const image::Image& reference, const image::Mask* mask) {
  check_image(metric, "test", test);
  // FlipFeatures (one image) and flip against them (whose reference was checked when it was
  // prepared) pass one image in both roles: scan it once.
  if (&reference != &test) check_image(metric, "reference", reference);
  const std::string name(metric);
  if (test.width != reference.width || test.height != reference.height) {
    throw QualityError(name + ": test image is " + size_text(test.width, test.height) +
                       " but reference is " + size_text(reference.width, reference.height));
  }
  if (mask == nullptr) return;
  if (mask->width != test.width || mask->height != test.height ||
      mask->values.size() != test.pixel_count()) {
    throw QualityError(name + ": mask is " + size_text(mask->width, mask->height) + " with " +
                       std::to_string(mask->values.size()) + " values but the images are " +
                       size_text(test.width, test.height));
  }
  if (mask->count() == 0) throw QualityError(name + ": mask selects no pixel");
}

}  // namespace skinsim::quality
