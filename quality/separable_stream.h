// Separable 2D filtering of several image channels at once, streamed through a few rows of
// memory: each task takes a chunk of output rows, generates the source rows it needs, filters
// them along x into a ring of the last 2R+1 rows, then along y, and hands each finished output
// row to a sink. No full-size intermediate planes are allocated (page faults dominated the
// full-plane version), and pixels outside the image repeat the nearest edge pixel.
//
// Every output value is the same sequence of float operations whatever the chunking or thread
// count (x taps in order, then y taps in order), so results are bitwise deterministic.
#pragma once

#include <functional>
#include <span>
#include <vector>

namespace skinsim::quality {

// A 1D kernel of odd length 2r+1; tap i applies to offset i - r.
struct RowFilter {
  int source_channel;  // which source channel to filter along x
  std::vector<float> kernel;
};
struct ColumnFilter {
  int row_filter;  // which row-filtered channel to filter along y
  std::vector<float> kernel;
};

// Columns [begin, end) of a row; none when begin >= end.
struct Columns {
  int begin = 0;
  int end = 0;
  bool empty() const { return begin >= end; }
};

struct SeparableStream {
  int width = 0;
  int height = 0;
  int source_channels = 0;
  std::vector<RowFilter> row_filters;
  std::vector<ColumnFilter> column_filters;
  // The output columns wanted in each row (`height` entries), or empty for every pixel. Each
  // chunk of rows then computes only the columns its rows want, and the source columns
  // those read; a chunk that wants none is skipped. A computed value is the same whatever
  // else is computed.
  std::vector<Columns> wanted;
};

// Writes row y of every source channel: channels[c] points to `width` floats, of which the
// stream reads `columns`.
using SourceRowFn = std::function<void(int y, Columns columns, std::span<float* const> channels)>;
// Receives output row y: filtered[f] is column filter f's result (`width` floats), valid in
// `columns` (which hold every column the row wants, and perhaps more).
using OutputRowFn =
    std::function<void(int y, Columns columns, std::span<const float* const> filtered)>;

// Runs the filters over the image (or its wanted columns) in parallel (TBB) chunks of rows.
void run_separable_stream(const SeparableStream& stream, const SourceRowFn& source,
                          const OutputRowFn& sink);

// A normalised (sum 1) sampled Gaussian exp(-x^2 / (2 sigma^2)), x = -radius..radius.
std::vector<float> gaussian_kernel(double sigma, int radius);

}  // namespace skinsim::quality
