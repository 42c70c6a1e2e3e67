#include "driver/sweep/frame_comparison.h"

#include "quality/metrics.h"

namespace skinsim::driver {

namespace {

results::FrameComparison summarise(const quality::FlipResult& flip, const image::Mask* mask) {
  const quality::FlipStatistics s = quality::flip_statistics(flip.map, mask);
  results::FrameComparison c;
  c.flip_mean = s.mean;
  c.flip_p99 = s.p99;
  c.visible_px = static_cast<double>(s.visible_pixels);
  c.visible = s.visible();
  return c;
}

}  // namespace

results::FrameComparison compare_frames(const image::Image& test, const image::Image& against,
                                        const image::Mask* mask) {
  return summarise(quality::flip(test, against, mask), mask);
}

results::FrameComparison compare_frames(const image::Image& test,
                                        const quality::FlipFeatures& against,
                                        const image::Mask* mask) {
  return summarise(quality::flip(test, against, mask), mask);
}

}  // namespace skinsim::driver
