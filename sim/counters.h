// Work counters of one render pass on the emulated GPU: what the tiler (TA) and the per-tile
// renderer (3D) did. Pure data: gpu_model/ turns them into time and bytes with a device
// profile. All counts are exact integers and independent of the host thread count.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "shading/op_profile.h"

namespace skinsim::sim {

enum class Filter : std::uint8_t { kNearest = 0, kBilinear = 1, kTrilinear = 2 };
constexpr int kFilterCount = 3;

// Texture-unit work and texture-cache traffic.
struct TextureCounters {
  // Sample instructions executed, by filter kind actually applied (a trilinear sample whose
  // LOD falls on a single level is still counted as trilinear: the TMU pays for it).
  std::uint64_t samples_by_filter[kFilterCount] = {0, 0, 0};
  std::uint64_t samples_dependent = 0;    // of which dependent reads
  std::uint64_t samples_wide_format = 0;  // of which from RGBA16F/RGBA32F textures
  std::uint64_t texels_touched = 0;       // texel reads before caching
  std::uint64_t cache_line_accesses = 0;  // distinct cache lines looked up per sample
  std::uint64_t cache_misses = 0;
  std::uint64_t dram_bytes = 0;  // cache misses x line size

  std::uint64_t samples() const {
    return samples_by_filter[0] + samples_by_filter[1] + samples_by_filter[2];
  }
  void add(const TextureCounters& o) {
    for (int i = 0; i < kFilterCount; ++i) samples_by_filter[i] += o.samples_by_filter[i];
    samples_dependent += o.samples_dependent;
    samples_wide_format += o.samples_wide_format;
    texels_touched += o.texels_touched;
    cache_line_accesses += o.cache_line_accesses;
    cache_misses += o.cache_misses;
    dram_bytes += o.dram_bytes;
  }
  bool operator==(const TextureCounters&) const = default;
};

// Fragments one draw (one shader program) shaded in one tile.
struct DrawFragments {
  std::uint32_t draw = 0;  // index into PassCounters::draws
  std::uint64_t fragments_shaded = 0;
  // Fragments that passed the depth test when met in submission order: what a GPU shading
  // after an early depth test, without deferred HSR, would shade (>= fragments_shaded).
  std::uint64_t fragments_early_z = 0;
  bool operator==(const DrawFragments&) const = default;
};

enum class TileCoverage : std::uint8_t { kEmpty = 0, kPartial = 1, kFull = 2 };

struct TileCounters {
  std::uint16_t tile_x = 0;
  std::uint16_t tile_y = 0;
  std::uint8_t core = 0;  // emulated GPU core the tile was assigned to
  TileCoverage coverage = TileCoverage::kEmpty;
  std::uint32_t triangle_refs = 0;           // triangles in this tile's list
  std::uint64_t fragments_depth_tested = 0;  // ISP work: pixels a triangle covers
  std::uint64_t samples_covered = 0;         // MSAA samples of those pixels it covers
  std::uint64_t samples_in_tile = 0;         // pixels x samples held in tile memory
  std::uint64_t resolves = 0;                // pixels box-averaged from samples at the store
  std::uint64_t fragments_shaded = 0;
  std::uint64_t fragments_blended = 0;        // of shaded: read-modify-write in tile memory
  std::uint32_t hsr_flushes = 0;              // tag-buffer flushes forced by blended draws
  std::vector<DrawFragments> shaded_by_draw;  // sorted by draw index
  TextureCounters texture;
  std::uint64_t color_load_bytes = 0;   // DRAM -> tile memory at tile start (LoadOp::kLoad)
  std::uint64_t color_store_bytes = 0;  // tile memory -> DRAM at tile end (resolve)
  std::uint64_t depth_load_bytes = 0;
  std::uint64_t depth_store_bytes = 0;
  bool operator==(const TileCounters&) const = default;
};

// One draw call as the GPU saw it.
struct DrawCounters {
  std::string vertex_program;
  std::string fragment_program;
  OpProfile vertex_profile;
  OpProfile fragment_profile;
  bool blended = false;
  std::uint64_t vertices_shaded = 0;
  std::uint64_t triangles_in = 0;
  std::uint64_t fragments_shaded = 0;
  bool operator==(const DrawCounters&) const = default;
};

// Equality (defaulted, every field) is what tests of determinism and replay compare.
struct PassCounters {
  std::string name;
  int width = 0;
  int height = 0;
  int tile_size = 32;
  int tiles_x = 0;
  int tiles_y = 0;
  int cores = 1;
  int samples = 1;  // MSAA samples per pixel
  // Tile-memory bytes one sample of one pixel takes: colour (the target's format) plus
  // depth/stencil; what decides how many samples a device's tile memory holds.
  int tile_bytes_per_sample = 0;

  // Tiler (TA).
  std::uint64_t vertices_shaded = 0;
  std::uint64_t triangles_in = 0;
  std::uint64_t triangles_culled_backface = 0;
  std::uint64_t triangles_culled_frustum = 0;     // entirely outside a clip plane
  std::uint64_t triangles_culled_degenerate = 0;  // zero area or no pixel centre covered box
  std::uint64_t triangles_clipped = 0;            // crossed the near plane and were clipped
  std::uint64_t triangles_binned = 0;             // after clipping (a clipped one may yield 2)
  std::uint64_t tile_refs = 0;                    // sum over tiles of triangle_refs
  std::uint64_t varying_floats_per_vertex = 0;    // max over draws: parameter-buffer vertex size
  std::uint64_t tiles_empty = 0;
  std::uint64_t tiles_partial = 0;
  std::uint64_t tiles_full = 0;

  // Per-tile renderer (3D), summed over tiles.
  std::uint64_t tiles_rendered = 0;  // tiles inside the render area
  std::uint64_t fragments_depth_tested = 0;
  std::uint64_t samples_covered = 0;
  std::uint64_t samples_in_tile = 0;
  std::uint64_t resolves = 0;
  std::uint64_t fragments_shaded = 0;
  std::uint64_t fragments_blended = 0;
  std::uint64_t hsr_flushes = 0;
  TextureCounters texture;
  std::uint64_t color_load_bytes = 0;
  std::uint64_t color_store_bytes = 0;
  std::uint64_t depth_load_bytes = 0;
  std::uint64_t depth_store_bytes = 0;

  std::vector<DrawCounters> draws;
  std::vector<TileCounters> tiles;  // row-major, tiles_x * tiles_y (outside render area: empty)
  bool operator==(const PassCounters&) const = default;
};

}  // namespace skinsim::sim
