// Per-pixel conversions of whole images (to bytes, to false colour, out of a render target)
// on TBB's threads. Each index writes only its own output, so the result is the same for any
// thread count.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>

namespace skinsim {

// body(i) for every i in [0, count), in blocks of 65536 (a 2048x1536 frame in 48 tasks).
template <class Body>
void for_each_pixel(std::size_t count, const Body& body) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, std::size_t{1} << 16),
                    [&](const tbb::blocked_range<std::size_t>& pixels) {
                      for (std::size_t i = pixels.begin(); i < pixels.end(); ++i) body(i);
                    });
}

}  // namespace skinsim
