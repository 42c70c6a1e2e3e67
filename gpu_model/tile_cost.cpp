#include "gpu_model/tile_cost.h"

#include <algorithm>
#include <cmath>

#include "gpu_model/model_terms.h"

namespace skinsim::gpu_model {
namespace {

bool has_work(const sim::TileCounters& t) {
  return t.triangle_refs != 0 || t.fragments_depth_tested != 0 || t.fragments_shaded != 0 ||
         t.texture.samples() != 0 || t.color_load_bytes != 0 || t.color_store_bytes != 0 ||
         t.depth_load_bytes != 0 || t.depth_store_bytes != 0;
}

double texture_cycles(const sim::TextureCounters& tex, const DeviceProfile& p) {
  const double tmus = p.tmus_per_core.value;
  // Dependent reads cannot be prefetched before the program runs (Imagination forum): each
  // adds exposed stall cycles, spread over the core's TMUs.
  return texture_ops(tex, p) / (tmus * p.bilinear_per_tmu_clock.value) +
         static_cast<double>(tex.samples_dependent) * p.dependent_read_stall_cycles.value / tmus;
}

}  // namespace

int msaa_tile_passes(const sim::PassCounters& pass, double tile_memory_bytes) {
  if (pass.samples <= 1) return 1;
  const double pixels = static_cast<double>(pass.tile_size) * pass.tile_size;
  const double per_pixel = static_cast<double>(pass.tile_bytes_per_sample);
  const double memory = tile_memory_bytes > 0.0 ? tile_memory_bytes : pixels * per_pixel;
  return std::max(1, static_cast<int>(std::ceil(pixels * pass.samples * per_pixel / memory)));
}

double TileWork::cycles() const {
  return overhead_cycles + std::max({isp_cycles, alu_cycles, texture_cycles});
}

Unit TileWork::bottleneck() const {
  Unit unit = Unit::kOverhead;
  double most = overhead_cycles;
  // Fixed order keeps ties deterministic.
  for (const auto& [u, c] : {std::pair{Unit::kIsp, isp_cycles}, std::pair{Unit::kAlu, alu_cycles},
                             std::pair{Unit::kTexture, texture_cycles}}) {
    if (c > most) {
      most = c;
      unit = u;
    }
  }
  return unit;
}

TileWork estimate_tile(const sim::TileCounters& tile, const sim::PassCounters& pass,
                       const std::vector<double>& fragment_cycles, const DeviceProfile& p) {
  TileWork w;
  if (!has_work(tile)) return w;

  // ISP: every rasterised fragment is depth/stencil tested before shading (deferred HSR,
  // PowerVR Architecture Guide); blended draws force tag-buffer flushes.
  w.isp_cycles =
      static_cast<double>(tile.fragments_depth_tested) / p.isp_fragments_per_clock_per_core.value +
      tile.hsr_flushes * p.isp_hsr_flush_cycles.value;

  // USSE: visible fragments x their program's issue cycles, plus blending, which SGX runs as
  // appended USSE code; spread over the core's pipes.
  // Without deferred HSR the overdraw an early depth test lets through is shaded too.
  double pipe_cycles = static_cast<double>(tile.fragments_blended) * p.blend_cycles.value;
  double visible = 0.0, shaded = 0.0;
  for (const sim::DrawFragments& df : tile.shaded_by_draw) {
    const double fragments = fragments_shaded_on(df, p);
    pipe_cycles += fragments * fragment_cycles[df.draw];
    visible += static_cast<double>(df.fragments_shaded);
    shaded += fragments;
  }
  w.alu_cycles = pipe_cycles / p.pipes_per_core.value;

  // The extra fragments sample like the visible ones (the counters measured those only);
  // their texels are the tile's own, so they add TMU time but no DRAM bytes.
  w.texture_cycles = texture_cycles(tile.texture, p) * (visible > 0.0 ? shaded / visible : 1.0);
  // MSAA: the ISP tests a pixel's samples in one slot (Arm: 4x MSAA at close to full
  // speed; the rate per sample is unpublished for SGX) and the samples are resolved as the
  // tile is written back, on chip: neither adds cycles or DRAM bytes here. What grows is the
  // number of tiles when the samples overflow tile memory: each pass over a part of the tile
  // pays the per-tile cost and reads the tile's parameter-buffer list again (an upper
  // bound: a smaller tile's list is shorter).
  const int passes = msaa_tile_passes(pass, p.tile_memory_bytes.value);
  w.overhead_cycles = p.tile_overhead_cycles.value * passes;

  // The 3D reads the tile's control stream and the primitive data it references back from
  // the parameter buffer (hardware.md).
  const double vertex_bytes =
      pb_vertex_bytes(p, static_cast<double>(pass.varying_floats_per_vertex));
  w.dram.parameter_read = static_cast<double>(tile.triangle_refs) * passes *
                          (p.pb_bytes_per_tile_ref.value + p.pb_bytes_per_triangle.value +
                           p.pb_vertices_read_per_tile_ref.value * vertex_bytes);
  w.dram.texture = static_cast<double>(tile.texture.dram_bytes);
  w.dram.color_load = compressed_target_bytes(tile.color_load_bytes, p);
  w.dram.color_store = compressed_target_bytes(tile.color_store_bytes, p);
  w.dram.depth_load = compressed_target_bytes(tile.depth_load_bytes, p);
  w.dram.depth_store = compressed_target_bytes(tile.depth_store_bytes, p);
  return w;
}

}  // namespace skinsim::gpu_model
