#include "quality/separable_stream.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>

#include "util/float_lanes.h"
#include "util/simd_dispatch.h"

namespace skinsim::quality {
namespace {

// Rows per task: large enough that the 2R halo rows each chunk recomputes stay a small
// overhead, small enough to balance two or more threads.
constexpr int kChunkRows = 128;

int radius_of(const std::vector<float>& kernel) {
  return static_cast<int>(kernel.size() / 2);
}

// out[x] for x in [begin, end) = sum over k of kernel[k] * taps[k][x], summed from 0 in k's
// order. Each output is that very sequence of float operations, as if a loop over k added one
// tap to all outputs at a time, but a block of outputs stays in registers across the taps
// (eight independent sums hide the additions' latency) instead of going to memory and back
// per tap. Vec is 4 float lanes (SSE2) or 8 (AVX): each output's operations are the same
// whichever holds it, so both paths give the same bits.
//
// The helpers are always inlined, so that in the AVX path they are AVX code too: SSE2 code
// run while the AVX registers' upper halves are in use is several times slower on some
// processors, and GCC does not clear them (vzeroupper) before a call it makes as a tail call.

// Outputs from x in blocks of kBlock while a whole block fits; returns where it stopped.
template <class Vec, int kBlock>
[[gnu::always_inline]] inline int weighted_sum_blocks(std::span<const float* const> taps,
                                                      const std::vector<float>& kernel, int x,
                                                      int end, float* out) {
  constexpr int kLanes = static_cast<int>(sizeof(Vec) / sizeof(float));
  constexpr int kSums = kBlock / kLanes;
  for (; x + kBlock <= end; x += kBlock) {
    std::array<Vec, kSums> sum{};
    for (std::size_t k = 0; k < kernel.size(); ++k) {
      Vec weight;
      for (int lane = 0; lane < kLanes; ++lane) weight[lane] = kernel[k];
      const float* src = taps[k] + x;
      for (int i = 0; i < kSums; ++i) {
        Vec v;
        std::memcpy(&v, src + kLanes * i, sizeof v);
        sum[i] += weight * v;
      }
    }
    std::memcpy(out + x, sum.data(), sizeof sum);
  }
  return x;
}

// Outputs [x, end) four at a time, the last group partial.
[[gnu::always_inline]] inline void weighted_sum_tail(std::span<const float* const> taps,
                                                     const std::vector<float>& kernel, int x,
                                                     int end, float* out) {
  for (; x < end; x += 4) {
    const int n = std::min(4, end - x);
    Float4 sum{};
    for (std::size_t k = 0; k < kernel.size(); ++k)
      sum += splat(kernel[k]) * load_lanes(taps[k] + x, n);
    store_lanes(out + x, sum, n);
  }
}

void weighted_sum_sse2(std::span<const float* const> taps, const std::vector<float>& kernel,
                       int begin, int end, float* out) {
  const int x = weighted_sum_blocks<Float4, 32>(taps, kernel, begin, end, out);
  weighted_sum_tail(taps, kernel, x, end, out);
}

// No FMA in target "avx": a multiply and an add stay two roundings, as in SSE2.
[[gnu::target("avx")]] void weighted_sum_avx(std::span<const float* const> taps,
                                             const std::vector<float>& kernel, int begin, int end,
                                             float* out) {
  using Float8 = float __attribute__((vector_size(32)));
  int x = weighted_sum_blocks<Float8, 64>(taps, kernel, begin, end, out);
  x = weighted_sum_blocks<Float8, 32>(taps, kernel, x, end, out);
  weighted_sum_tail(taps, kernel, x, end, out);
}

void weighted_sum(std::span<const float* const> taps, const std::vector<float>& kernel, int begin,
                  int end, float* out) {
  if (use_avx()) {
    weighted_sum_avx(taps, kernel, begin, end, out);
  } else {
    weighted_sum_sse2(taps, kernel, begin, end, out);
  }
}

// Filters columns [out_columns) of one row along x with edge-clamped borders: out[x] reads
// source[clamp(x - r .. x + r)]. `padded` is scratch of >= width + 2r, `taps` of >= 2r + 1.
void filter_row(const float* source, int width, const std::vector<float>& kernel,
                Columns out_columns, float* padded, const float** taps, float* out) {
  const int radius = radius_of(kernel);
  const int begin = out_columns.begin, end = out_columns.end;
  // padded[i] = source[clamp(i - radius, 0, width - 1)] for i in [begin, end + 2r): the
  // border's copies of the first and last pixel, and one copy of the row between them.
  int i = begin;
  for (; i < end + 2 * radius && i < radius; ++i) padded[i] = source[0];
  const int inside_end = std::min(end + 2 * radius, width + radius);
  if (i < inside_end) {
    std::memcpy(padded + i, source + (i - radius),
                static_cast<std::size_t>(inside_end - i) * sizeof(float));
    i = inside_end;
  }
  for (; i < end + 2 * radius; ++i) padded[i] = source[width - 1];
  for (std::size_t k = 0; k < kernel.size(); ++k) taps[k] = padded + k;  // out[x]'s tap k
  weighted_sum({taps, kernel.size()}, kernel, begin, end, out);
}

class ChunkWorker {
 public:
  ChunkWorker(const SeparableStream& stream, const SourceRowFn& source, const OutputRowFn& sink)
      : s_(stream), source_(source), sink_(sink) {
    halo_ = 0;
    for (const ColumnFilter& f : s_.column_filters) halo_ = std::max(halo_, radius_of(f.kernel));
    widest_ = 0;
    for (const RowFilter& f : s_.row_filters) widest_ = std::max(widest_, radius_of(f.kernel));
    ring_rows_ = 2 * halo_ + 1;
    const std::size_t w = static_cast<std::size_t>(s_.width);
    source_rows_.resize(w * s_.source_channels);
    padded_.resize(w + 2 * static_cast<std::size_t>(widest_));
    taps_.resize(2 * static_cast<std::size_t>(std::max(widest_, halo_)) + 1);
    ring_.resize(w * ring_rows_ * s_.row_filters.size());
    output_.resize(w * s_.column_filters.size());
    for (int c = 0; c < s_.source_channels; ++c) source_pointers_.push_back(&source_rows_[w * c]);
    for (std::size_t f = 0; f < s_.column_filters.size(); ++f)
      output_pointers_.push_back(&output_[w * f]);
  }

  // Output rows [y_begin, y_end), columns `columns` of each.
  void run(int y_begin, int y_end, Columns columns) {
    columns_ = columns;
    source_columns_ = {std::max(0, columns.begin - widest_),
                       std::min(s_.width, columns.end + widest_)};
    for (int sy = y_begin - halo_; sy < y_begin + halo_; ++sy) push_source_row(sy);
    for (int y = y_begin; y < y_end; ++y) {
      push_source_row(y + halo_);
      for (std::size_t f = 0; f < s_.column_filters.size(); ++f) filter_column(f, y);
      sink_(y, columns_, output_pointers_);
    }
  }

 private:
  float* ring_row(std::size_t row_filter, int sy) {
    const int slot = ((sy % ring_rows_) + ring_rows_) % ring_rows_;
    return &ring_[(row_filter * ring_rows_ + slot) * static_cast<std::size_t>(s_.width)];
  }

  // Generates source row sy (clamped into the image) and filters it along x into the ring.
  void push_source_row(int sy) {
    source_(std::clamp(sy, 0, s_.height - 1), source_columns_, source_pointers_);
    for (std::size_t f = 0; f < s_.row_filters.size(); ++f) {
      const RowFilter& filter = s_.row_filters[f];
      filter_row(source_pointers_[filter.source_channel], s_.width, filter.kernel, columns_,
                 padded_.data(), taps_.data(), ring_row(f, sy));
    }
  }

  void filter_column(std::size_t f, int y) {
    const ColumnFilter& filter = s_.column_filters[f];
    const int radius = radius_of(filter.kernel);
    for (int k = 0; k <= 2 * radius; ++k) taps_[k] = ring_row(filter.row_filter, y + k - radius);
    weighted_sum({taps_.data(), filter.kernel.size()}, filter.kernel, columns_.begin, columns_.end,
                 output_pointers_[f]);
  }

  const SeparableStream& s_;
  const SourceRowFn& source_;
  const OutputRowFn& sink_;
  int halo_ = 0;
  int widest_ = 0;
  int ring_rows_ = 1;
  Columns columns_;         // output (and row-filtered) columns of the current chunk
  Columns source_columns_;  // the source columns those read
  std::vector<float> source_rows_;
  std::vector<float> padded_;
  std::vector<const float*> taps_;  // the rows or offsets a filter's taps read
  std::vector<float> ring_;
  std::vector<float> output_;
  std::vector<float*> source_pointers_;
  std::vector<float*> output_pointers_;
};

// The columns rows [y_begin, y_end) want together (all when the stream names none).
Columns chunk_columns(const SeparableStream& stream, int y_begin, int y_end) {
  if (stream.wanted.empty()) return {0, stream.width};
  Columns all{stream.width, 0};
  for (int y = y_begin; y < y_end; ++y) {
    const Columns& row = stream.wanted[y];
    if (row.empty()) continue;
    all = {std::min(all.begin, row.begin), std::max(all.end, row.end)};
  }
  return all;
}

}  // namespace

void run_separable_stream(const SeparableStream& stream, const SourceRowFn& source,
                          const OutputRowFn& sink) {
  if (!stream.wanted.empty() && stream.wanted.size() != static_cast<std::size_t>(stream.height)) {
    throw std::invalid_argument("separable stream: wanted columns for " +
                                std::to_string(stream.wanted.size()) + " rows of " +
                                std::to_string(stream.height));
  }
  const int chunks = (stream.height + kChunkRows - 1) / kChunkRows;
  tbb::parallel_for(tbb::blocked_range<int>(0, chunks), [&](const tbb::blocked_range<int>& range) {
    ChunkWorker worker(stream, source, sink);
    for (int chunk = range.begin(); chunk < range.end(); ++chunk) {
      const int y_begin = chunk * kChunkRows;
      const int y_end = std::min(stream.height, (chunk + 1) * kChunkRows);
      const Columns columns = chunk_columns(stream, y_begin, y_end);
      if (!columns.empty()) worker.run(y_begin, y_end, columns);
    }
  });
}

std::vector<float> gaussian_kernel(double sigma, int radius) {
  std::vector<double> taps(2 * radius + 1);
  double sum = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    taps[i + radius] = std::exp(-(i * i) / (2.0 * sigma * sigma));
    sum += taps[i + radius];
  }
  std::vector<float> kernel(taps.size());
  for (std::size_t i = 0; i < taps.size(); ++i) kernel[i] = static_cast<float>(taps[i] / sum);
  return kernel;
}

}  // namespace skinsim::quality
