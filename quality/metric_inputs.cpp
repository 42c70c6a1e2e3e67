#include "quality/metric_inputs.h"

#include <cmath>
#include <string>

#include "quality/error.h"

namespace skinsim::quality {
namespace {

std::string size_text(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

void check_image(std::string_view metric, std::string_view role, const Image& image) {
  const std::string where = std::string(metric) + ": " + std::string(role) + " image";
  if (image.width <= 0 || image.height <= 0) {
    throw QualityError(where + " is empty (" + size_text(image.width, image.height) + ")");
  }
  if (image.rgb.size() != image.pixel_count()) {
    throw QualityError(where + " holds " + std::to_string(image.rgb.size()) +
                       " pixels but is declared " + size_text(image.width, image.height));
  }
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    const glm::vec3& p = image.rgb[i];
    if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b)) {
      throw QualityError(where + " has a non-finite value at pixel (" +
                         std::to_string(i % image.width) + ", " + std::to_string(i / image.width) +
                         ")");
    }
  }
}

}  // namespace

void check_metric_inputs(std::string_view metric, const Image& test, const Image& reference,
                         const Mask* mask) {
  check_image(metric, "test", test);
  check_image(metric, "reference", reference);
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
