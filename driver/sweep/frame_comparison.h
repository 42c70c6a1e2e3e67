// One frame against another as the sweep's verdicts see them: FLIP over a mask (every pixel
// if none), its mean and 99th percentile, and whether the difference is visible
// (quality::FlipStatistics::visible). The sweep's comparisons and `skinsim compare` share it.
#pragma once

#include "image/image.h"
#include "quality/metrics.h"
#include "results/sweep_table.h"

namespace skinsim::driver {

// `test` against `against` (same size); `against` is left for the caller to name.
results::FrameComparison compare_frames(const image::Image& test, const image::Image& against,
                                        const image::Mask* mask);
// The same against a frame prepared once for many comparisons (identical results).
results::FrameComparison compare_frames(const image::Image& test,
                                        const quality::FlipFeatures& against,
                                        const image::Mask* mask);

}  // namespace skinsim::driver
