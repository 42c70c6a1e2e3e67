// Image quality of a frame against the reference: PSNR, SSIM and FLIP over the skin pixels
// (the reference's skin mask) and over the whole frame, plus a false-coloured FLIP map.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "image/image.h"
#include "pipeline/reference/reference.h"
#include "quality/metrics.h"

namespace skinsim::driver {

struct FrameQuality {
  // Keys: psnr_frame, ssim_frame, flip_frame, visible_frame_pct/px, and psnr_skin,
  // ssim_skin, flip_skin, flip_skin_p95/p99, visible_skin_pct/px when the reference shows skin
  // (has_skin_metrics). visible_*: pixels whose FLIP error is above
  // quality::flip_visibility_threshold(), as a percentage of the region and as a count.
  std::map<std::string, double> metrics;
  image::Image error_map;  // FLIP error, magma colour map
  bool has_skin_metrics() const { return metrics.count("flip_skin") > 0; }
};

// The reference as an 8-bit display image and its skin mask, computed once and shared by
// every configuration compared against it.
struct ReferenceImages {
  image::Image image;
  image::Mask skin;
  // The reference's FLIP features, when many frames are compared with it (a sweep): the
  // comparisons then filter only the frames. Without them each comparison streams both.
  std::shared_ptr<const quality::FlipFeatures> flip_features;
};
ReferenceImages reference_images(const pipeline::ReferenceFrame& reference);

// `test`: the frame as an image (to_image of its render target).
FrameQuality evaluate_quality(const image::Image& test, const ReferenceImages& reference);

}  // namespace skinsim::driver
