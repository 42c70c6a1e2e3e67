#include "driver/frame_comparison.h"

#include "quality/metrics.h"

namespace skinsim::driver {

namespace {

reports::FrameComparison summarise(const quality::FlipResult& flip, const quality::Mask* mask) {
  const quality::FlipStatistics s = quality::flip_statistics(flip.map, mask);
  reports::FrameComparison c;
  c.flip_mean = s.mean;
  c.flip_p99 = s.p99;
  c.visible_px = static_cast<double>(s.visible_pixels);
  c.visible = s.visible();
  return c;
}

}  // namespace

reports::FrameComparison compare_frames(const quality::Image& test, const quality::Image& against,
                                        const quality::Mask* mask) {
  return summarise(quality::flip(test, against, mask), mask);
}

reports::FrameComparison compare_frames(const quality::Image& test,
                                        const quality::FlipFeatures& against,
                                        const quality::Mask* mask) {
  return summarise(quality::flip(test, against, mask), mask);
}

}  // namespace skinsim::driver
