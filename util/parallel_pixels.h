// Per-pixel conversions of whole images (to bytes, to false colour, out of a render target)
// on TBB's threads. Each index writes only its own output, so the result is the same for any
// thread count.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>

namespace skinsim {

// Indices per task: a 2048x1536 frame's pixels in 48 tasks.
inline constexpr std::size_t kPixelBlock = std::size_t{1} << 16;

// body(begin, end) for runs of consecutive indices that together cover [0, count), each at
// most about kPixelBlock long: for loops that take a run at once (SIMD conversions).
template <class Body>
void for_each_block(std::size_t count, const Body& body) {
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, count, kPixelBlock),
      [&](const tbb::blocked_range<std::size_t>& run) { body(run.begin(), run.end()); });
}

// body(i) for every i in [0, count).
template <class Body>
void for_each_pixel(std::size_t count, const Body& body) {
  for_each_block(count, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) body(i);
  });
}

}  // namespace skinsim
