#include "sim/texture_cache.h"

#include <stdexcept>
#include <string>

namespace skinsim::sim {

namespace {
constexpr std::uint32_t kEmpty = ~std::uint32_t{0};

bool is_pow2(std::uint32_t v) {
  return v != 0 && (v & (v - 1)) == 0;
}
}  // namespace

TextureCache::TextureCache(const TextureCacheConfig& config)
    : line_bytes_(config.line_bytes),
      line_shift_(0),
      sets_(0),
      set_mask_(0),
      index_bits_(0),
      fold_steps_(0),
      ways_(config.associativity) {
  if (!is_pow2(config.line_bytes) || config.associativity == 0 ||
      config.size_bytes < config.line_bytes * config.associativity ||
      config.size_bytes % (config.line_bytes * config.associativity) != 0) {
    throw std::invalid_argument(
        "texture cache: size " + std::to_string(config.size_bytes) + " B, line " +
        std::to_string(config.line_bytes) + " B, " + std::to_string(config.associativity) +
        " ways do not form a cache (line must be a power of two, size a multiple of line x ways)");
  }
  line_shift_ = line_shift_of(line_bytes_);
  sets_ = config.size_bytes / (config.line_bytes * config.associativity);
  set_mask_ = is_pow2(sets_) ? sets_ - 1 : 0;
  if (config.set_index == SetIndex::kXorFold && sets_ > 1) {
    // Folding index-wide bit chunks is only defined for a power-of-two set count (as in
    // hardware, where the index is a bit field).
    if (set_mask_ == 0) {
      throw std::invalid_argument(
          "texture cache: XOR-folded set index needs a power-of-two set "
          "count, got " +
          std::to_string(sets_) + " sets");
    }
    while ((1u << index_bits_) < sets_) ++index_bits_;
    // Enough doubling steps that 2^steps chunks cover all 64 bits of a line number.
    while ((std::uint64_t{index_bits_} << fold_steps_) < 64) ++fold_steps_;
  }
  tags_.assign(static_cast<size_t>(sets_) * ways_, kEmpty);
}

void TextureCache::replay(const TextureLineLog& log, TextureCounters& counters) {
  std::uint64_t misses = 0;
  for (const std::uint32_t line : log.lines()) misses += !access_line(line);
  counters.cache_misses += misses;
  counters.dram_bytes += misses * line_bytes_;
}

}  // namespace skinsim::sim
