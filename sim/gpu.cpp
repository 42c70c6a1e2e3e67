#include "sim/gpu.h"

#include <tbb/task_arena.h>

#include <stdexcept>

#include "sim/binner.h"
#include "sim/geometry.h"
#include "sim/pass_memo.h"
#include "sim/sample_pattern.h"
#include "sim/tile_stage.h"

namespace skinsim::sim {

int core_of_tile(int tile_index, int cores) {
  return tile_index % cores;
}

Gpu::Gpu(GpuConfig config) : config_(config) {
  if (config_.tile_size < 4 || config_.tile_size > 256) {
    throw std::invalid_argument("GPU tile size must be in [4, 256], got " +
                                std::to_string(config_.tile_size));
  }
  if (config_.cores < 1 || config_.cores > 64) {
    throw std::invalid_argument("GPU core count must be in [1, 64], got " +
                                std::to_string(config_.cores));
  }
  if (config_.threads < 0) throw std::invalid_argument("thread count must be >= 0");
  // Every parallel loop of a render runs in this arena, so --threads 1 keeps all of it on
  // the calling thread.
  arena_ = config_.threads == 0 ? std::make_unique<tbb::task_arena>()
                                : std::make_unique<tbb::task_arena>(config_.threads);
}

Gpu::~Gpu() = default;

PassCounters Gpu::execute(const RenderPassDesc& pass) {
  const RenderTarget* size_from = pass.color ? pass.color : pass.depth;
  if (!size_from || size_from->width <= 0 || size_from->height <= 0) {
    throw std::invalid_argument("render pass '" + pass.name + "' has no colour or depth target");
  }
  try {
    sample_pattern(pass.samples);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("render pass '" + pass.name + "': " + e.what());
  }
  if (pass.depth_load == LoadOp::kLoad) {
    throw std::invalid_argument("render pass '" + pass.name + "': depth load is not supported");
  }
  if (pass.depth) {
    if (!is_depth_format(pass.depth->format) || !pass.store_depth) {
      throw std::invalid_argument("render pass '" + pass.name + "': depth target '" +
                                  pass.depth->name + "' needs a depth format and store_depth");
    }
    if (pass.color &&
        (pass.color->width != pass.depth->width || pass.color->height != pass.depth->height)) {
      throw std::invalid_argument("render pass '" + pass.name +
                                  "': colour and depth targets differ in size");
    }
  }
  for (const DrawCall& d : pass.draws) {
    if (!d.vertex_program || (pass.color && !d.fragment_program)) {
      throw std::invalid_argument("render pass '" + pass.name + "': draw without programs");
    }
    if (d.vertex_program->varying_floats() > kMaxVaryings) {
      throw std::invalid_argument("vertex program '" + d.vertex_program->name() +
                                  "' writes more than " + std::to_string(kMaxVaryings) +
                                  " varying floats");
    }
    // Tiles resolve while others still sample, so reading a target being rendered would
    // make the image depend on tile order (undefined on the GPU too).
    for (const Texture2D* t : d.textures.textures) {
      for (const RenderTarget* own : {pass.color, pass.depth}) {
        if (t && own && t->level(0).texels == own->pixels.data()) {
          throw std::invalid_argument("render pass '" + pass.name + "' samples its own target '" +
                                      own->name + "'");
        }
      }
    }
  }
  std::optional<PassKey> key;
  std::optional<PassCounters> replayed;
  if (memo_) {
    memo_->note_sampled(pass);
    key = pass_key(pass, config_);
    if (key) replayed = memo_->replay(*key, pass);
  }
  PassCounters result;
  if (replayed) {
    result = std::move(*replayed);
  } else {
    arena_->execute([&] { result = execute_impl(pass); });
    if (key) memo_->store(*key, pass, result);
  }
  if (capture_) capture_(pass);
  return result;
}

PassCounters Gpu::execute_impl(const RenderPassDesc& pass) {
  PassCounters c;
  c.name = pass.name;
  c.width = pass_target(pass).width;
  c.height = pass_target(pass).height;
  c.tile_size = config_.tile_size;
  c.tiles_x = (c.width + c.tile_size - 1) / c.tile_size;
  c.tiles_y = (c.height + c.tile_size - 1) / c.tile_size;
  c.cores = config_.cores;
  c.samples = pass.samples;
  c.tile_bytes_per_sample = (pass.color ? bytes_per_texel(pass.color->format) : 0) +
                            config_.depth_stencil_bytes_per_pixel;
  c.draws.resize(pass.draws.size());
  for (size_t d = 0; d < pass.draws.size(); ++d) {
    const DrawCall& draw = pass.draws[d];
    c.draws[d].vertex_program = draw.vertex_program->name();
    c.draws[d].vertex_profile = draw.vertex_program->profile();
    if (draw.fragment_program) {
      c.draws[d].fragment_program = draw.fragment_program->name();
      c.draws[d].fragment_profile = draw.fragment_program->profile();
    }
    c.draws[d].blended = draw.blend != BlendMode::kOpaque;
  }

  TileGrid grid;
  grid.tile_size = c.tile_size;
  grid.tiles_x = c.tiles_x;
  grid.tiles_y = c.tiles_y;
  grid.width = c.width;
  grid.height = c.height;
  grid.area = tile_aligned_area(pass, c.tile_size);
  grid.sample_reach = sample_pattern(pass.samples).reach;

  const SetupTriangles setup = run_geometry(pass, grid.area, c);
  const TileBins bins = bin_triangles(setup, grid, c);

  const int tile_count = c.tiles_x * c.tiles_y;
  c.tiles.resize(tile_count);
  for (int i = 0; i < tile_count; ++i) {
    c.tiles[i].tile_x = static_cast<std::uint16_t>(i % c.tiles_x);
    c.tiles[i].tile_y = static_cast<std::uint16_t>(i / c.tiles_x);
    c.tiles[i].core = static_cast<std::uint8_t>(core_of_tile(i, c.cores));
    c.tiles[i].coverage = bins.coverage[i];
    c.tiles[i].triangle_refs = static_cast<std::uint32_t>(bins.lists[i].size());
  }

  render_tiles(pass, config_, setup, grid, bins, c);

  for (const TileCounters& t : c.tiles) {
    if (!grid.in_area(t.tile_x, t.tile_y)) continue;
    ++c.tiles_rendered;
    c.fragments_depth_tested += t.fragments_depth_tested;
    c.samples_covered += t.samples_covered;
    c.samples_in_tile += t.samples_in_tile;
    c.resolves += t.resolves;
    c.fragments_shaded += t.fragments_shaded;
    c.fragments_blended += t.fragments_blended;
    c.hsr_flushes += t.hsr_flushes;
    c.texture.add(t.texture);
    c.color_load_bytes += t.color_load_bytes;
    c.color_store_bytes += t.color_store_bytes;
    c.depth_load_bytes += t.depth_load_bytes;
    c.depth_store_bytes += t.depth_store_bytes;
    for (const DrawFragments& df : t.shaded_by_draw) {
      c.draws[df.draw].fragments_shaded += df.fragments_shaded;
    }
  }
  return c;
}

}  // namespace skinsim::sim
