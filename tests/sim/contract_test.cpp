// The emulator's contracts (SKINSIM_DCHECK, util/check.h) fire on an index out of range and
// exit with status 3, an internal error. Compiled only where they are on (SKINSIM_DEBUG_CHECKS:
// the sanitizer build); in Release they are compiled out, so there is nothing to test.
#ifdef SKINSIM_DEBUG_CHECKS

#include <gtest/gtest.h>

#include <vector>

#include "sim/binner.h"
#include "sim/geometry.h"
#include "sim/render_pass.h"
#include "sim/render_target.h"
#include "sim/shader_io.h"
#include "sim/texture.h"
#include "sim/texture_line_log.h"
#include "sim/texture_unit.h"
#include "sim/tile_renderer.h"

namespace skinsim::sim {
namespace {

const char* const kBug = "internal error \\(a bug in skinsim\\).*contract";

TEST(ContractDeathTest, VaryingSlotPastTheLast) {
  ExecVertexOut out;
  out.set(kMaxVaryings - 1, 1.0f);  // the last slot is fine
  EXPECT_EXIT(out.set(kMaxVaryings, 1.0f), testing::ExitedWithCode(3), kBug);
  EXPECT_EXIT(out.set(kMaxVaryings - 1, glm::vec2(1.0f)), testing::ExitedWithCode(3), kBug);
}

TEST(ContractDeathTest, TextureBindingPastTheLast) {
  TextureBindings bindings;
  ExecTexUnit tex(nullptr, nullptr);
  tex.bind(&bindings);
  EXPECT_EXIT(tex.sample(kMaxTextureBindings, glm::vec2(0.5f)), testing::ExitedWithCode(3),
              "contract \\(0 <= binding < kMaxTextureBindings\\) failed: binding = 8");
  EXPECT_EXIT(tex.sample(-1, glm::vec2(0.5f)), testing::ExitedWithCode(3), kBug);
}

TEST(ContractDeathTest, TexelOutsideItsLevel) {
  const std::vector<glm::vec4> texels(4, glm::vec4(1.0f));
  const LevelView level{2, 2, texels.data()};
  EXPECT_EQ(level.at(1, 1), glm::vec4(1.0f));
  EXPECT_EXIT(level.at(2, 0), testing::ExitedWithCode(3), "x = 2, width = 2");
  EXPECT_EXIT(level.at(0, -1), testing::ExitedWithCode(3), "y = -1, height = 2");
  const RenderTarget target("t", 2, 2, TexelFormat::kRGBA8);
  EXPECT_EXIT(target.at(0, 2), testing::ExitedWithCode(3), kBug);
}

TEST(ContractDeathTest, TileOutsideTheGrid) {
  RenderTarget target("t", 32, 32, TexelFormat::kRGBA8);
  RenderPassDesc pass;
  pass.color = &target;
  const SetupTriangles setup;
  TileGrid grid;
  grid.tiles_x = grid.tiles_y = 1;
  grid.area = {0, 0, 32, 32};
  grid.width = grid.height = 32;
  const GpuConfig config;
  TileRenderer renderer(pass, setup, grid, config);
  TileCounters counters;
  TextureLineLog lines;
  renderer.render(0, 0, {}, counters, lines);  // the one tile is fine
  EXPECT_EXIT(renderer.render(1, 0, {}, counters, lines), testing::ExitedWithCode(3),
              "tx = 1, grid_.tiles_x = 1");
}

}  // namespace
}  // namespace skinsim::sim

#endif  // SKINSIM_DEBUG_CHECKS
