#include "driver/frame_quality.h"

#include <stdexcept>

#include "driver/images.h"
#include "quality/error_map.h"
#include "quality/metrics.h"

namespace skinsim::driver {

ReferenceImages reference_images(const pipeline::ReferenceFrame& reference) {
  ReferenceImages r;
  // Quantise to 8 bits as a display would: the frames compared against it are RGBA8.
  r.image = to_image(reference.frame);
  for (glm::vec3& c : r.image.rgb) c = glm::round(c * 255.0f) / 255.0f;
  r.skin.width = reference.frame.width;
  r.skin.height = reference.frame.height;
  r.skin.values = reference.skin_mask;
  return r;
}

FrameQuality evaluate_quality(const sim::RenderTarget& frame, const ReferenceImages& reference) {
  if (frame.width != reference.image.width || frame.height != reference.image.height) {
    throw std::invalid_argument("frame and reference sizes differ");
  }
  const quality::Image test = to_image(frame);
  const quality::FlipResult flip_skin = quality::flip(test, reference.image, &reference.skin);
  FrameQuality q;
  q.metrics["psnr_skin"] = quality::psnr(test, reference.image, &reference.skin);
  q.metrics["ssim_skin"] = quality::ssim(test, reference.image, &reference.skin);
  q.metrics["flip_skin"] = flip_skin.mean;
  q.metrics["psnr_frame"] = quality::psnr(test, reference.image);
  q.metrics["ssim_frame"] = quality::ssim(test, reference.image);
  // The FLIP map covers every pixel; only its mean depends on the mask.
  double sum = 0.0;
  for (const float v : flip_skin.map.values) sum += v;
  q.metrics["flip_frame"] = flip_skin.map.values.empty() ? 0.0 : sum / flip_skin.map.values.size();
  q.error_map = quality::false_colour(flip_skin.map);
  return q;
}

}  // namespace skinsim::driver
