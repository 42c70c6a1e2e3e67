#include "driver/frame/images.h"

#include "util/parallel_pixels.h"

namespace skinsim::driver {

image::Image to_image(const sim::RenderTarget& target, float scale) {
  image::Image img;
  img.width = target.width;
  img.height = target.height;
  img.rgb.resize(target.pixels.size());
  for_each_pixel(target.pixels.size(), [&](std::size_t i) {
    img.rgb[i] = glm::clamp(glm::vec3(target.pixels[i]) * scale, 0.0f, 1.0f);
  });
  return img;
}

void write_png(const sim::RenderTarget& target, const std::filesystem::path& path, float scale) {
  image::save_png(to_image(target, scale), path);
}

}  // namespace skinsim::driver
