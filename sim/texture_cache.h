// Set-associative LRU texture cache of one emulated GPU core. Geometry (size, line size,
// associativity) comes from the device profile; SGX554's real figures are unpublished,
// so the profile states its assumption (hardware.md).
#pragma once

#include <cstdint>
#include <vector>

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
  bool access(std::uint64_t address);
  std::uint32_t line_bytes() const { return line_bytes_; }
  std::uint64_t line_of(std::uint64_t address) const { return address >> line_shift_; }
  void clear();

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
  std::vector<std::uint64_t> tags_;
};

inline bool TextureCache::access(std::uint64_t address) {
  const std::uint64_t line = address >> line_shift_;
  std::uint64_t set;
  if (fold_steps_ != 0) {  // constant per cache, so the branch predicts perfectly
    std::uint64_t folded = line;
    for (std::uint32_t k = 0; k < fold_steps_; ++k) folded ^= folded >> (index_bits_ << k);
    set = folded & set_mask_;
  } else {
    set = set_mask_ ? (line & set_mask_) : line % sets_;
  }
  std::uint64_t* ways = &tags_[set * ways_];
  if (ways[0] == line) return true;  // already the most recent: the common hit
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
