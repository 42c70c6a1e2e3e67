#include "driver/frame/frame_quality.h"

#include <stdexcept>

#include "driver/frame/images.h"
#include "quality/error_map.h"
#include "quality/metrics.h"

namespace skinsim::driver {

ReferenceImages reference_images(const pipeline::ReferenceFrame& reference) {
  ReferenceImages r;
  // Quantise to 8 bits as a display would: the frames compared against it are RGBA8.
  r.image = to_image(reference.frame);
  image::round_to_saved_png(r.image);
  r.skin.width = reference.frame.width;
  r.skin.height = reference.frame.height;
  r.skin.values = reference.skin_mask;
  return r;
}

FrameQuality evaluate_quality(const image::Image& test, const ReferenceImages& reference) {
  if (test.width != reference.image.width || test.height != reference.image.height) {
    throw std::invalid_argument("frame and reference sizes differ");
  }
  FrameQuality q;
  q.metrics["psnr_frame"] = quality::psnr(test, reference.image);
  // One SSIM map serves the frame's and the skin's mean.
  image::ScalarMap ssim_map;
  q.metrics["ssim_frame"] = quality::ssim(test, reference.image, nullptr, &ssim_map);
  // With no skin pixel in the reference the skin metrics do not exist (the caller says why):
  // the frame metrics and the FLIP map still do.
  const bool has_skin = reference.skin.count() > 0;
  const image::Mask* skin_mask = has_skin ? &reference.skin : nullptr;
  const quality::FlipResult flip = reference.flip_features
                                       ? quality::flip(test, *reference.flip_features, skin_mask)
                                       : quality::flip(test, reference.image, skin_mask);
  if (has_skin) {
    q.metrics["psnr_skin"] = quality::psnr(test, reference.image, &reference.skin);
    q.metrics["ssim_skin"] = quality::map_mean(ssim_map, &reference.skin);
    q.metrics["flip_skin"] = flip.mean;
    // The mean hides local artefacts (a halo, a shadow edge): the tail and the visible area
    // show them (quality::flip_statistics).
    const quality::FlipStatistics skin = quality::flip_statistics(flip.map, &reference.skin);
    q.metrics["flip_skin_p95"] = skin.p95;
    q.metrics["flip_skin_p99"] = skin.p99;
    q.metrics["visible_skin_pct"] = skin.visible_percent();
    q.metrics["visible_skin_px"] = static_cast<double>(skin.visible_pixels);
  }
  const std::size_t visible_frame = quality::flip_visible_pixels(flip.map);
  q.metrics["visible_frame_pct"] = quality::visible_percent(visible_frame, flip.map.values.size());
  q.metrics["visible_frame_px"] = static_cast<double>(visible_frame);
  // The FLIP map covers every pixel; only its mean depends on the mask.
  double sum = 0.0;
  for (const float v : flip.map.values) sum += v;
  q.metrics["flip_frame"] = flip.map.values.empty() ? 0.0 : sum / flip.map.values.size();
  q.error_map = quality::false_colour(flip.map);
  return q;
}

}  // namespace skinsim::driver
