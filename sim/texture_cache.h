// Set-associative LRU texture cache of one emulated GPU core. Geometry (size, line size,
// associativity) comes from the device profile; SGX554's real figures are unpublished,
// so the profile states its assumption (hardware.md).
#pragma once

#include <emmintrin.h>  // SSE2, in every x86-64 processor

#include <cstdint>
#include <vector>

#include "sim/counters.h"
#include "sim/texture_line_log.h"

namespace skinsim::sim {

// How a line number picks its set. Whether SGX hashes the index is unpublished, so the
// device profile states it (texture.cache_set_hash; emulator.md).
enum class SetIndex {
  // line % sets. Same-size textures in page-aligned regions, read at the same UV, land in
  // the same set and conflict.
  kModulo,
  // All higher line bits XOR-folded into the index bits, as many L1/L2 designs do to break
  // power-of-two strides ("XOR-based placement", Gonzalez et al., ICS 1997). Needs a
  // power-of-two set count.
  kXorFold,
};

struct TextureCacheConfig {
  std::uint32_t size_bytes = 8 * 1024;
  std::uint32_t line_bytes = 64;
  std::uint32_t associativity = 4;
  SetIndex set_index = SetIndex::kModulo;
};

class TextureCache {
 public:
  explicit TextureCache(const TextureCacheConfig& config);

  // Looks up the line holding `address`; returns true on a hit. A miss fills the line,
  // evicting the least recently used way of its set.
  // Addresses lie below 2^32 lines (texture_unit.h), so a line number is 32 bits.
  bool access(std::uint64_t address) {
    return access_line(static_cast<std::uint32_t>(address >> line_shift_));
  }
  // Looks up a tile's recorded lines in order, counting its misses and their DRAM bytes.
  void replay(const TextureLineLog& log, TextureCounters& counters);

 private:
  std::uint32_t line_bytes_;
  std::uint32_t line_shift_;
  std::uint32_t sets_;
  std::uint64_t set_mask_;    // sets_ - 1 when sets_ is a power of two, else 0 (use modulo)
  std::uint32_t index_bits_;  // log2(sets_) when folding
  // XOR-fold steps; 0 means no folding. Step k XORs in the value shifted by index_bits_ << k,
  // so after n steps the low index_bits_ hold the XOR of 2^n index-wide chunks of the line.
  std::uint32_t fold_steps_;
  std::uint32_t ways_;
  // Per set, `ways_` line tags ordered most recently used first; kEmpty marks a free way.
  std::vector<std::uint32_t> tags_;

  bool access_line(std::uint32_t line);
  std::uint64_t set_of(std::uint32_t line) const;
  bool access_4_ways(std::uint32_t* ways, std::uint32_t line);
};

inline std::uint64_t TextureCache::set_of(std::uint32_t line) const {
  if (fold_steps_ != 0) {  // constant per cache, so the branch predicts perfectly
    std::uint64_t folded = line;
    for (std::uint32_t k = 0; k < fold_steps_; ++k) folded ^= folded >> (index_bits_ << k);
    return folded & set_mask_;
  }
  return set_mask_ ? (line & set_mask_) : line % sets_;
}

// The 4-way set of every shipped profile, without a branch on where the line is: which of
// its replays hit, and how far back, is data the branch predictor cannot learn. The four
// tags compare at once; the ways before the hit (all but the last on a miss, which evicts
// it) move back one and the line takes way 0.
inline bool TextureCache::access_4_ways(std::uint32_t* ways, std::uint32_t line) {
  // kKeepFrom[i]: the lanes after way i, which keep their tags (lane 0 first).
  alignas(16) static constexpr std::int32_t kKeepFrom[4][4] = {
      {0, -1, -1, -1}, {0, 0, -1, -1}, {0, 0, 0, -1}, {0, 0, 0, 0}};
  const __m128i tags = _mm_loadu_si128(reinterpret_cast<const __m128i*>(ways));
  const __m128i same = _mm_cmpeq_epi32(tags, _mm_set1_epi32(static_cast<int>(line)));
  const int hit_mask = _mm_movemask_ps(_mm_castsi128_ps(same));  // one bit at most
  const int way = hit_mask ? __builtin_ctz(static_cast<unsigned>(hit_mask)) : 3;
  const __m128i keep = _mm_load_si128(reinterpret_cast<const __m128i*>(kKeepFrom[way]));
  const __m128i moved = _mm_or_si128(_mm_slli_si128(tags, 4),  // way k takes way k - 1's tag
                                     _mm_cvtsi32_si128(static_cast<int>(line)));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(ways),
                   _mm_or_si128(_mm_and_si128(keep, tags), _mm_andnot_si128(keep, moved)));
  return hit_mask != 0;
}

inline bool TextureCache::access_line(std::uint32_t line) {
  std::uint32_t* ways = &tags_[set_of(line) * ways_];
  if (ways_ == 4) return access_4_ways(ways, line);  // constant per cache
  if (ways[0] == line) return true;                  // already the most recent: the common hit
  for (std::uint32_t i = 1; i < ways_; ++i) {
    if (ways[i] == line) {
      for (std::uint32_t j = i; j > 0; --j) ways[j] = ways[j - 1];  // move to front
      ways[0] = line;
      return true;
    }
  }
  for (std::uint32_t j = ways_ - 1; j > 0; --j) ways[j] = ways[j - 1];
  ways[0] = line;
  return false;
}

}  // namespace skinsim::sim
