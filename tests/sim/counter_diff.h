// Names the first field in which two passes' counters differ, for a failing
// EXPECT_EQ(a, b) on PassCounters (whose defaulted operator== compares every field) to say
// where: "tiles[12].texture.cache_misses: 40 != 41". Fields not listed here are still
// compared by operator==; the message then says only that the passes differ.
#pragma once

#include <sstream>
#include <string>

#include "sim/counters.h"

namespace skinsim::sim::testing {

class CounterDiff {
 public:
  std::string first(const PassCounters& a, const PassCounters& b) {
    field("name", a.name, b.name);
#define SKINSIM_FIELD(f) field(#f, a.f, b.f)
    SKINSIM_FIELD(width);
    SKINSIM_FIELD(height);
    SKINSIM_FIELD(tile_size);
    SKINSIM_FIELD(tiles_x);
    SKINSIM_FIELD(tiles_y);
    SKINSIM_FIELD(cores);
    SKINSIM_FIELD(samples);
    SKINSIM_FIELD(tile_bytes_per_sample);
    SKINSIM_FIELD(vertices_shaded);
    SKINSIM_FIELD(triangles_in);
    SKINSIM_FIELD(triangles_culled_backface);
    SKINSIM_FIELD(triangles_culled_frustum);
    SKINSIM_FIELD(triangles_culled_degenerate);
    SKINSIM_FIELD(triangles_clipped);
    SKINSIM_FIELD(triangles_binned);
    SKINSIM_FIELD(tile_refs);
    SKINSIM_FIELD(varying_floats_per_vertex);
    SKINSIM_FIELD(tiles_empty);
    SKINSIM_FIELD(tiles_partial);
    SKINSIM_FIELD(tiles_full);
    SKINSIM_FIELD(tiles_rendered);
    fragments(a, b);
    SKINSIM_FIELD(hsr_flushes);
    texture("texture.", a.texture, b.texture);
    bytes(a, b);
    SKINSIM_FIELD(draws.size());
    SKINSIM_FIELD(tiles.size());
    for (std::size_t i = 0; i < a.draws.size() && i < b.draws.size(); ++i) {
      const std::string at = "draws[" + std::to_string(i) + "].";
      const DrawCounters &da = a.draws[i], &db = b.draws[i];
      field(at + "vertex_program", da.vertex_program, db.vertex_program);
      field(at + "fragment_program", da.fragment_program, db.fragment_program);
      field(at + "vertex_profile", da.vertex_profile == db.vertex_profile, true);
      field(at + "fragment_profile", da.fragment_profile == db.fragment_profile, true);
      field(at + "blended", da.blended, db.blended);
      field(at + "vertices_shaded", da.vertices_shaded, db.vertices_shaded);
      field(at + "triangles_in", da.triangles_in, db.triangles_in);
      field(at + "fragments_shaded", da.fragments_shaded, db.fragments_shaded);
    }
    for (std::size_t i = 0; i < a.tiles.size() && i < b.tiles.size(); ++i) {
      tile("tiles[" + std::to_string(i) + "].", a.tiles[i], b.tiles[i]);
    }
#undef SKINSIM_FIELD
    if (found_.empty() && !(a == b)) return "a field CounterDiff does not list";
    return found_;
  }

 private:
  template <typename T>
  void field(const std::string& name, const T& a, const T& b) {
    if (!found_.empty() || a == b) return;
    std::ostringstream s;
    s << name << ": " << +a << " != " << +b;
    found_ = s.str();
  }
  void field(const std::string& name, const std::string& a, const std::string& b) {
    if (found_.empty() && a != b) found_ = name + ": '" + a + "' != '" + b + "'";
  }
  void field(const std::string& name, TileCoverage a, TileCoverage b) {
    field(name, static_cast<int>(a), static_cast<int>(b));
  }
  // The fields PassCounters and TileCounters share.
  template <typename C>
  void fragments(const C& a, const C& b, const std::string& at = "") {
    field(at + "fragments_depth_tested", a.fragments_depth_tested, b.fragments_depth_tested);
    field(at + "samples_covered", a.samples_covered, b.samples_covered);
    field(at + "samples_in_tile", a.samples_in_tile, b.samples_in_tile);
    field(at + "resolves", a.resolves, b.resolves);
    field(at + "fragments_shaded", a.fragments_shaded, b.fragments_shaded);
    field(at + "fragments_blended", a.fragments_blended, b.fragments_blended);
  }
  template <typename C>
  void bytes(const C& a, const C& b, const std::string& at = "") {
    field(at + "color_load_bytes", a.color_load_bytes, b.color_load_bytes);
    field(at + "color_store_bytes", a.color_store_bytes, b.color_store_bytes);
    field(at + "depth_load_bytes", a.depth_load_bytes, b.depth_load_bytes);
    field(at + "depth_store_bytes", a.depth_store_bytes, b.depth_store_bytes);
  }
  void texture(const std::string& at, const TextureCounters& a, const TextureCounters& b) {
    for (int f = 0; f < kFilterCount; ++f) {
      field(at + "samples_by_filter[" + std::to_string(f) + "]", a.samples_by_filter[f],
            b.samples_by_filter[f]);
    }
    field(at + "samples_dependent", a.samples_dependent, b.samples_dependent);
    field(at + "samples_wide_format", a.samples_wide_format, b.samples_wide_format);
    field(at + "texels_touched", a.texels_touched, b.texels_touched);
    field(at + "cache_line_accesses", a.cache_line_accesses, b.cache_line_accesses);
    field(at + "cache_misses", a.cache_misses, b.cache_misses);
    field(at + "dram_bytes", a.dram_bytes, b.dram_bytes);
  }
  void tile(const std::string& at, const TileCounters& a, const TileCounters& b) {
    field(at + "tile_x", a.tile_x, b.tile_x);
    field(at + "tile_y", a.tile_y, b.tile_y);
    field(at + "core", a.core, b.core);
    field(at + "coverage", a.coverage, b.coverage);
    field(at + "triangle_refs", a.triangle_refs, b.triangle_refs);
    fragments(a, b, at);
    field(at + "hsr_flushes", a.hsr_flushes, b.hsr_flushes);
    field(at + "shaded_by_draw.size()", a.shaded_by_draw.size(), b.shaded_by_draw.size());
    for (std::size_t i = 0; i < a.shaded_by_draw.size() && i < b.shaded_by_draw.size(); ++i) {
      const std::string d = at + "shaded_by_draw[" + std::to_string(i) + "].";
      field(d + "draw", a.shaded_by_draw[i].draw, b.shaded_by_draw[i].draw);
      field(d + "fragments_shaded", a.shaded_by_draw[i].fragments_shaded,
            b.shaded_by_draw[i].fragments_shaded);
      field(d + "fragments_early_z", a.shaded_by_draw[i].fragments_early_z,
            b.shaded_by_draw[i].fragments_early_z);
    }
    texture(at + "texture.", a.texture, b.texture);
    bytes(a, b, at);
  }

  std::string found_;
};

// The first differing field of `a` and `b`, or "" when they are equal.
inline std::string first_counter_difference(const PassCounters& a, const PassCounters& b) {
  return CounterDiff().first(a, b);
}

}  // namespace skinsim::sim::testing
