// What one render pass on the emulated GPU is: a target, load/store actions, an optional
// render area and an ordered list of draws. Each pass is one "render" in PowerVR terms:
// binned by the tiler, then rendered tile by tile, then resolved.
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/program.h"
#include "sim/render_target.h"
#include "sim/texture_cache.h"
#include "sim/texture_unit.h"

namespace skinsim::sim {

enum class CullMode : std::uint8_t { kNone, kBack, kFront };
enum class BlendMode : std::uint8_t { kOpaque, kAlpha, kAdditive };
enum class LoadOp : std::uint8_t { kClear, kLoad, kDontCare };

struct Geometry {
  VertexAttributes attributes;
  std::size_t vertex_count = 0;
  const std::uint32_t* indices = nullptr;
  std::size_t index_count = 0;  // 3 per triangle
};

struct DrawCall {
  Geometry geometry;
  std::shared_ptr<const VertexProgram> vertex_program;
  // Null in a depth-only pass (no colour target): the ISP tests and writes depth and no
  // fragment is shaded, as for a PowerVR render with no colour attachment.
  std::shared_ptr<const FragmentProgram> fragment_program;
  TextureBindings textures;
  CullMode cull = CullMode::kBack;  // front faces are counter-clockwise, as in OpenGL
  BlendMode blend = BlendMode::kOpaque;
  bool depth_test = true;
  bool depth_write = true;
};

// Pixel rectangle [x0, x1) x [y0, y1). Tiles outside it are neither rendered nor resolved.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct RenderPassDesc {
  std::string name;
  RenderTarget* color = nullptr;  // null: a depth-only pass into `depth`
  LoadOp color_load = LoadOp::kClear;
  glm::vec4 clear_color{0.0f};
  bool store_color = true;
  LoadOp depth_load = LoadOp::kClear;  // depth lives in tile memory; kLoad is not supported
  bool store_depth = false;            // depth is discarded at the end of the render
  // Where stored depth goes (a kDepth16/kDepth24 target of the pass's size, to be sampled
  // by a later pass, e.g. a shadow map); without it a store is counted but not kept.
  RenderTarget* depth = nullptr;
  std::optional<PixelRect> render_area;  // default: the whole target
  // MSAA samples per pixel (1, 2 or 4, sim/sample_pattern.h): coverage and depth are kept
  // per sample in tile memory, each covered primitive is shaded once per pixel, and the
  // samples are box-averaged into the target as the tile is stored (on chip: the samples
  // never reach DRAM). Stored depth takes sample 0 (Vulkan's SAMPLE_ZERO resolve).
  int samples = 1;
  std::vector<DrawCall> draws;
};

// The target that gives a pass its size: the colour target, or the depth target of a
// depth-only pass.
inline const RenderTarget& pass_target(const RenderPassDesc& pass) {
  return pass.color ? *pass.color : *pass.depth;
}

// The emulated GPU's fixed configuration (from the device profile).
struct GpuConfig {
  int tile_size = 32;
  int cores = 4;
  TextureCacheConfig texture_cache;
  // On-chip depth+stencil bytes per pixel: what a depth store/load moves (hardware.md:
  // 32-bit float depth + 8-bit stencil).
  int depth_stencil_bytes_per_pixel = 5;
  int threads = 0;  // host worker threads; 0 = all hardware threads, 1 = synchronous
};

}  // namespace skinsim::sim
