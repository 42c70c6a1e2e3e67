// The cache lines one tile's texture samples requested, in request order. A tile shades on
// any host thread and records here; its emulated core's texture cache replays the log
// afterwards, in the core's tile order (TextureCache::replay), which is the hit/miss
// sequence of shading that core's tiles in order with the cache live (docs/emulator.md,
// "Cores, threads and determinism").
#pragma once

#include <bit>
#include <cstdint>
#include <vector>

namespace skinsim::sim {

// log2 of a cache line's bytes, a power of two (TextureCache rejects any other size).
inline std::uint32_t line_shift_of(std::uint32_t line_bytes) {
  return static_cast<std::uint32_t>(std::countr_zero(line_bytes));
}

class TextureLineLog {
 public:
  explicit TextureLineLog(std::uint32_t line_bytes = 64) : line_shift_(line_shift_of(line_bytes)) {}

  std::uint64_t line_of(std::uint64_t address) const { return address >> line_shift_; }
  std::uint32_t line_shift() const { return line_shift_; }
  // Records a request for `line` (line_of an address). A request for the line requested just
  // before is not recorded: the cache holds that line as its set's most recent, so the
  // request hits and changes nothing (consecutive taps of a blur, or the levels of a magnified
  // trilinear sample, often share a line). Line numbers fit 32 bits: texture addresses lie
  // below kMaxTextureBindings x kBindingAddressStride = 2^31 (static_assert in texture_unit.h).
  void add(std::uint64_t line) {
    const auto l = static_cast<std::uint32_t>(line);
    if (lines_.empty() || lines_.back() != l) lines_.push_back(l);
  }
  // What add() of each of `other`'s requests gives: other holds no repeat, so only its first
  // can repeat this log's last.
  void append(const TextureLineLog& other) {
    const std::vector<std::uint32_t>& more = other.lines_;
    if (more.empty()) return;
    const bool repeat = !lines_.empty() && lines_.back() == more.front();
    lines_.insert(lines_.end(), more.begin() + (repeat ? 1 : 0), more.end());
  }
  // The requests to replay, in order: all but the repeats of the line just before.
  const std::vector<std::uint32_t>& lines() const { return lines_; }
  void clear() { lines_.clear(); }  // keeps the capacity for the next tile

 private:
  std::uint32_t line_shift_;
  std::vector<std::uint32_t> lines_;
};

}  // namespace skinsim::sim
