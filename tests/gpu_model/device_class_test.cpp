// The modern device classes (docs/hardware.md): tile memory, hidden-surface removal by class,
// framebuffer compression, energy per frame, and the loader's checks of the new fields.
#include <gtest/gtest.h>

#include "gpu_model/energy.h"
#include "gpu_model/error.h"
#include "gpu_model/frame_cost.h"
#include "gpu_model/tile_memory.h"
#include "tests/gpu_model/test_support.h"

namespace skinsim::gpu_model {
namespace {

using testing::kDataDir;
using testing::parse_error;
using testing::shipped_text;

DeviceProfile device(const std::string& name) {
  return load_device_profile(name, kDataDir);
}

TEST(DeviceClass, EachModernProfileHasItsClass) {
  EXPECT_EQ(device("ipad4").gpu_class, GpuClass::kTbdr);
  EXPECT_EQ(device("a15").gpu_class, GpuClass::kTbdr);
  EXPECT_EQ(device("mali-g715").gpu_class, GpuClass::kTilerEarlyZ);
  EXPECT_EQ(device("adreno740").gpu_class, GpuClass::kBinning);
}

// Mali Valhall: 256 bits of colour per pixel at 16x16; Apple: 64 B per pixel halves the
// 32x32 tile to 32x16; Adreno's GMEM also holds depth.
TEST(DeviceClass, BigPixelsShrinkTheTileToFitTileMemory) {
  const DeviceProfile mali = device("mali-g715");
  EXPECT_EQ(fitted_tile(mali, 32.0).width, 16);
  EXPECT_EQ(fitted_tile(mali, 32.0).height, 16);
  EXPECT_EQ(fitted_tile(mali, 64.0).width, 16);
  EXPECT_EQ(fitted_tile(mali, 64.0).height, 8);
  const DeviceProfile a15 = device("a15");
  EXPECT_EQ(fitted_tile(a15, 32.0).height, 32);
  EXPECT_EQ(fitted_tile(a15, 64.0).width, 32);
  EXPECT_EQ(fitted_tile(a15, 64.0).height, 16);
  EXPECT_EQ(fitted_tile(a15, 128.0).width, 16);
  EXPECT_EQ(fitted_tile(a15, 128.0).height, 16);
  DeviceProfile adreno = device("adreno740");
  adreno.tile_memory_bytes.value = 256.0 * 256.0 * 8.0;  // exactly 4 B colour + 4 B depth
  EXPECT_EQ(fitted_tile(adreno, 4.0).height, 256);
  EXPECT_EQ(fitted_tile(adreno, 5.0).height, 128);
  // The SGX tile holds every pixel the pipeline draws (16 B colour at most).
  EXPECT_EQ(fitted_tile(device("ipad4"), 16.0).width, 32);
}

// Synthetic counters as the emulator would produce them for `p`: its tile size and cores.
sim::PassCounters& fit(sim::PassCounters& pass, const DeviceProfile& p) {
  pass.tile_size = static_cast<int>(p.tile_width.value);
  pass.cores = static_cast<int>(p.cores.value);
  pass.width = pass.tile_size * pass.tiles_x;
  pass.height = pass.tile_size * pass.tiles_y;
  return pass;
}

// One tile, one draw, `layers` full-tile layers: back to front every layer passes an early
// depth test in submission order; front to back only the first does.
sim::PassCounters layered_pass(std::uint64_t layers, bool back_to_front, const DeviceProfile& p) {
  sim::PassCounters pass = testing::make_pass(1, 1, 1);
  fit(pass, p);
  const std::uint32_t draw = testing::add_draw(pass, 10);
  constexpr std::uint64_t kPixels = 32 * 32;
  testing::shade(pass, 0, draw, kPixels);
  sim::TileCounters& t = pass.tiles[0];
  t.fragments_depth_tested = layers * kPixels;
  t.shaded_by_draw[0].fragments_early_z = back_to_front ? layers * kPixels : kPixels;
  testing::sum_tiles(pass);
  return pass;
}

double alu_cycles(const sim::PassCounters& pass, const DeviceProfile& p) {
  return estimate_frame({pass}, p).passes[0].busy_ms[static_cast<int>(Unit::kAlu)];
}

// Overdraw each class documents: TBDR shades the front layer in either order; early-Z
// shades all layers back to front, less what FPK / LRZ removes; front to back all equal.
TEST(DeviceClass, HiddenSurfaceRemovalFollowsTheClass) {
  constexpr std::uint64_t kLayers = 4;
  for (const char* name : {"ipad4", "a15", "mali-g715", "adreno740"}) {
    const DeviceProfile p = device(name);
    const double front = alu_cycles(layered_pass(kLayers, false, p), p);
    const double back = alu_cycles(layered_pass(kLayers, true, p), p);
    const double removed = p.hsr_overdraw_removed.value;
    // ALU time is linear in the fragments shaded: 1 layer plus the overdraw not removed.
    EXPECT_NEAR(back / front, 1.0 + (1.0 - removed) * (kLayers - 1), 1e-9) << name;
    if (p.gpu_class == GpuClass::kTbdr) {
      EXPECT_EQ(back, front) << name;
    } else {
      EXPECT_GT(back, front) << name;
    }
  }
}

TEST(DeviceClass, FramebufferCompressionScalesRenderTargetBytesOnly) {
  DeviceProfile p = device("mali-g715");
  sim::PassCounters pass = testing::make_pass(1, 1, 1);
  fit(pass, p);
  pass.tiles[0].color_store_bytes = 4096;
  pass.tiles[0].depth_load_bytes = 1024;
  pass.tiles[0].texture.dram_bytes = 640;
  pass.tiles[0].fragments_depth_tested = 1;
  testing::sum_tiles(pass);
  p.framebuffer_compression.value = 0.25;
  const DramBytes d = estimate_frame({pass}, p).passes[0].dram;
  EXPECT_DOUBLE_EQ(d.color_store, 1024.0);
  EXPECT_DOUBLE_EQ(d.depth_load, 256.0);
  EXPECT_DOUBLE_EQ(d.texture, 640.0);
}

TEST(DeviceClass, EnergyIsAdditiveOverPassesAndWithinItsRange) {
  for (const char* name : {"ipad4", "a15", "mali-g715", "adreno740"}) {
    const DeviceProfile p = device(name);
    sim::PassCounters a = layered_pass(3, true, p);
    a.name = "a";
    a.tiles[0].color_store_bytes = 4096;
    a.tiles[0].texture.samples_by_filter[1] = 500;
    testing::sum_tiles(a);
    sim::PassCounters b = layered_pass(2, false, p);
    b.name = "b";
    b.draws[0].vertices_shaded = 300;
    b.draws[0].vertex_profile.vector_ops = 12;
    b.draws[0].vertex_profile.vector_ops_mediump = 4;
    const FrameEnergy both = estimate_frame({a, b}, p).energy;
    const FrameEnergy only_a = estimate_frame({a}, p).energy;
    const FrameEnergy only_b = estimate_frame({b}, p).energy;
    ASSERT_EQ(both.passes.size(), 2u);
    EXPECT_DOUBLE_EQ(both.mj.total(), both.passes[0].mj.total() + both.passes[1].mj.total())
        << name;
    EXPECT_DOUBLE_EQ(both.mj.total(), only_a.mj.total() + only_b.mj.total()) << name;
    EXPECT_GT(both.mj.total(), 0.0) << name;
    EXPECT_GT(both.mj.dram, 0.0) << name;
    EXPECT_GT(both.mj.alu, 0.0) << name;
    EXPECT_GT(both.mj.texture, 0.0) << name;
    EXPECT_LT(both.low_mj, both.mj.total()) << name;
    EXPECT_GT(both.high_mj, both.mj.total()) << name;
    EXPECT_DOUBLE_EQ(both.low_mj, only_a.low_mj + only_b.low_mj) << name;
  }
}

// DRAM energy is bytes x pJ/B: 1e9 bytes at 100 pJ/B are 100 mJ.
TEST(DeviceClass, DramEnergyIsBytesTimesEnergyPerByte) {
  DeviceProfile p = device("ipad4");
  sim::PassCounters pass = testing::make_pass(1, 1, 1);
  fit(pass, p);
  pass.tiles[0].color_store_bytes = 1'000'000'000;
  pass.tiles[0].fragments_depth_tested = 1;
  testing::sum_tiles(pass);
  p.dram_pj_per_byte.value = 100.0;
  EXPECT_NEAR(estimate_frame({pass}, p).energy.mj.dram, 100.0, 1e-9);
  EXPECT_DOUBLE_EQ(average_power_mw(10.0, 20.0, 1000.0 / 30.0), 300.0);
  EXPECT_DOUBLE_EQ(average_power_mw(10.0, 50.0, 1000.0 / 30.0), 200.0);
}

TEST(DeviceClass, LoaderNamesBadClassAndTbdrOverdraw) {
  std::string text = shipped_text("ipad4");
  const std::string cls = "class = \"tbdr\"";
  std::string bad = text;
  bad.replace(bad.find(cls), cls.size(), "class = \"imr\"");
  EXPECT_NE(parse_error(bad).find("field 'device.class': must be one of tbdr"), std::string::npos)
      << parse_error(bad);
  std::string missing = text;
  missing.erase(missing.find(cls), cls.size());
  EXPECT_NE(parse_error(missing).find("field 'device.class': missing"), std::string::npos)
      << parse_error(missing);
  const std::string hsr = "[hsr.overdraw_removed]\nvalue = 1.0";
  std::string partial = text;
  partial.replace(partial.find(hsr), hsr.size(), "[hsr.overdraw_removed]\nvalue = 0.5");
  EXPECT_NE(parse_error(partial).find("field 'hsr.overdraw_removed': must be 1"), std::string::npos)
      << parse_error(partial);
  std::string energy = text;
  const std::string e = "[energy.depth_test_pj]";
  energy.replace(energy.find(e), e.size(), "[energy.unknown_pj]");
  EXPECT_NE(parse_error(energy).find("energy.unknown_pj"), std::string::npos)
      << parse_error(energy);
}

}  // namespace
}  // namespace skinsim::gpu_model
