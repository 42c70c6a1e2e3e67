#include "driver/images.h"

#include <algorithm>

namespace skinsim::driver {

quality::Image to_image(const sim::RenderTarget& target, float scale) {
  quality::Image img;
  img.width = target.width;
  img.height = target.height;
  img.rgb.resize(target.pixels.size());
  std::transform(
      target.pixels.begin(), target.pixels.end(), img.rgb.begin(),
      [scale](const glm::vec4& p) { return glm::clamp(glm::vec3(p) * scale, 0.0f, 1.0f); });
  return img;
}

void write_png(const sim::RenderTarget& target, const std::filesystem::path& path, float scale) {
  quality::save_png(to_image(target, scale), path);
}

}  // namespace skinsim::driver
