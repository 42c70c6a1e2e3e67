// Each model term on hand-computed cases. round_profile(): iPad 4 at 100 MHz (1e5 cycles/ms),
// 4 cores x 8 pipes, 2 TMUs/core, ISP 16 frag/clk, 32 cycles/tile, 3000 cycles/render,
// 17.06 GB/s x 0.6 achievable.
#include "gpu_model/pass_cost.h"

#include <gtest/gtest.h>

#include <type_traits>

#include "gpu_model/error.h"
#include "gpu_model/tile_cost.h"
#include "gpu_model/tile_schedule.h"
#include "test_support.h"

namespace skinsim::gpu_model {
namespace {

using testing::add_draw;
using testing::make_pass;
using testing::round_profile;
using testing::shade;
using testing::sum_tiles;

constexpr double kCyclesPerMs = 1e5;
constexpr double kBytesPerMs = 17.06 * 0.6 * 1e6;
constexpr double kRenderOverheadMs = 3000.0 / kCyclesPerMs;

double busy(const PassTiming& t, Unit u) {
  return t.busy_ms[static_cast<int>(u)];
}

TEST(PassCost, AluBoundPassTakesFragmentsTimesCyclesOverPipes) {
  const DeviceProfile p = round_profile();
  sim::PassCounters pass = make_pass(4, 4, 4);
  const auto draw = add_draw(pass, 10);
  for (std::size_t i = 0; i < pass.tiles.size(); ++i) shade(pass, i, draw, 1024);
  sum_tiles(pass);

  const PassTiming t = estimate_pass(pass, p);
  // N*K/(C*pipes*F) = 16384 * 10 / (4 * 8 * 1e5) ms, plus 4 tiles x 32 cycles per core and
  // the per-render overhead.
  const double alu_ms = 16384.0 * 10.0 / (4 * 8 * kCyclesPerMs);
  EXPECT_DOUBLE_EQ(busy(t, Unit::kAlu), alu_ms);
  EXPECT_DOUBLE_EQ(t.makespan_ms, alu_ms + 4 * 32 / kCyclesPerMs);
  EXPECT_DOUBLE_EQ(t.render_ms, t.makespan_ms + kRenderOverheadMs);
  EXPECT_DOUBLE_EQ(t.standalone_ms, t.render_ms);
  EXPECT_EQ(t.bottleneck, Unit::kAlu);
  EXPECT_DOUBLE_EQ(t.balance, 1.0);
  EXPECT_DOUBLE_EQ(t.ta_ms, 0.0);
  for (const TileTiming& tile : t.tiles) {
    EXPECT_EQ(tile.bottleneck, Unit::kAlu);
    EXPECT_DOUBLE_EQ(tile.alu_cycles, 1024.0 * 10 / 8);
    EXPECT_DOUBLE_EQ(tile.isp_cycles, 1024.0 / 16);
  }
  EXPECT_NEAR(t.utilisation[static_cast<int>(Unit::kAlu)], alu_ms / t.standalone_ms, 1e-12);
}

TEST(PassCost, BandwidthBoundPassTakesBytesOverBandwidth) {
  const DeviceProfile p = round_profile();
  sim::PassCounters pass = make_pass(2, 2, 4);
  for (sim::TileCounters& tile : pass.tiles) {
    tile.texture.samples_by_filter[1] = 1;
    tile.texture.dram_bytes = 25'000'000;
    tile.color_store_bytes = 4096;
  }
  sum_tiles(pass);
  const PassTiming t = estimate_pass(pass, p);
  const double bytes = 4 * (25'000'000.0 + 4096.0);
  EXPECT_DOUBLE_EQ(t.dram.total(), bytes);
  EXPECT_DOUBLE_EQ(t.render_bandwidth_ms, bytes / kBytesPerMs);
  EXPECT_DOUBLE_EQ(t.render_ms, bytes / kBytesPerMs + kRenderOverheadMs);
  EXPECT_EQ(t.bottleneck, Unit::kBandwidth);
}

TEST(PassCost, TilesWithoutWorkOrTrafficCostNothing) {
  const DeviceProfile p = round_profile();
  sim::PassCounters pass = make_pass(3, 1, 4);
  pass.tiles[1].color_store_bytes = 4096;  // a cleared tile is still stored
  sum_tiles(pass);
  const PassTiming t = estimate_pass(pass, p);
  EXPECT_DOUBLE_EQ(t.tiles[0].ms, 0.0);
  EXPECT_DOUBLE_EQ(t.tiles[1].ms, 32 / kCyclesPerMs);
  EXPECT_DOUBLE_EQ(t.tiles[2].ms, 0.0);
  EXPECT_DOUBLE_EQ(busy(t, Unit::kOverhead), 32 / kCyclesPerMs / 4 + kRenderOverheadMs);
}

TEST(PassCost, TextureTermCountsBilinearOpsAndDependentStalls) {
  const DeviceProfile p = round_profile();
  sim::PassCounters pass = make_pass(1, 1, 4);
  sim::TextureCounters& tex = pass.tiles[0].texture;
  tex.samples_by_filter[0] = 100;  // nearest: one TMU slot
  tex.samples_by_filter[1] = 1000;
  tex.samples_by_filter[2] = 500;  // two bilinear ops each
  tex.samples_dependent = 200;     // 2 stall cycles each, over 2 TMUs
  sum_tiles(pass);
  EXPECT_DOUBLE_EQ(estimate_pass(pass, p).tiles[0].texture_cycles, 2100.0 / 2 + 200.0 * 2 / 2);

  // 160 of 1600 samples wide: each costs 2x the tile's average of 2100/1600 ops.
  pass.tiles[0].texture.samples_wide_format = 160;
  sum_tiles(pass);
  const PassTiming t = estimate_pass(pass, p);
  EXPECT_DOUBLE_EQ(t.tiles[0].texture_cycles, (2100.0 + 160.0 * 2100.0 / 1600.0) / 2 + 200.0);
  EXPECT_EQ(t.tiles[0].bottleneck, Unit::kTexture);
  EXPECT_EQ(t.bottleneck, Unit::kOverhead);  // one small tile: the render overhead dominates
}

TEST(PassCost, IspTermAndBlendingCost) {
  const DeviceProfile p = round_profile();
  sim::PassCounters pass = make_pass(1, 1, 4);
  const auto draw = add_draw(pass, 1);
  shade(pass, 0, draw, 100);
  pass.draws[draw].blended = true;
  sim::TileCounters& tile = pass.tiles[0];
  tile.fragments_depth_tested = 3200;  // overdraw
  tile.fragments_blended = 100;
  tile.hsr_flushes = 2;
  sum_tiles(pass);
  const PassTiming t = estimate_pass(pass, p);
  EXPECT_DOUBLE_EQ(t.tiles[0].isp_cycles, 3200.0 / 16 + 2 * 64.0);
  EXPECT_DOUBLE_EQ(t.tiles[0].alu_cycles, (100.0 * 1 + 100.0 * 2) / 8);
  EXPECT_EQ(t.tiles[0].bottleneck, Unit::kIsp);
  EXPECT_DOUBLE_EQ(t.tiles[0].ms, (32 + 328.0) / kCyclesPerMs);
}

TEST(PassCost, TilerVertexSetupBinningAndParameterBuffer) {
  const DeviceProfile p = round_profile();
  sim::PassCounters pass = make_pass(2, 1, 4);
  sim::DrawCounters draw;
  draw.vertex_profile.vector_ops = 20;
  draw.vertices_shaded = 8000;
  draw.triangles_in = 2000;
  pass.draws.push_back(draw);
  pass.vertices_shaded = 8000;
  pass.triangles_in = 2000;
  pass.triangles_binned = 1800;
  pass.varying_floats_per_vertex = 8;
  pass.tiles[0].triangle_refs = 3000;
  pass.tiles[1].triangle_refs = 2000;
  sum_tiles(pass);

  const PassTiming t = estimate_pass(pass, p);
  EXPECT_DOUBLE_EQ(t.ta.vertex_cycles, 8000.0 * 20 / (4 * 8));
  EXPECT_DOUBLE_EQ(t.ta.setup_cycles, 2000.0 / (0.175 * 4));
  EXPECT_DOUBLE_EQ(t.ta.binning_cycles, 5000.0 / (1.0 * 4));
  // Vertex: 16 B position + 8 varyings x 4 B; 4 B per triangle; 4 B per tile reference.
  const double write = 8000.0 * 48 + 1800.0 * 4 + 5000.0 * 4;
  EXPECT_DOUBLE_EQ(t.dram.parameter_write, write);
  EXPECT_DOUBLE_EQ(t.ta.bandwidth_ms, write / kBytesPerMs);
  EXPECT_DOUBLE_EQ(t.ta_ms, 5000.0 / kCyclesPerMs);  // vertex shading is the slowest TA stage
  // Read back per reference: control word + triangle + 1 vertex.
  EXPECT_DOUBLE_EQ(t.dram.parameter_read, 5000.0 * (4 + 4 + 48));
}

TEST(PassCost, PerCauseBytesSumToTheTotal) {
  const DeviceProfile p = round_profile();
  sim::PassCounters pass = make_pass(3, 2, 4);
  pass.vertices_shaded = 300;
  pass.triangles_binned = 100;
  for (std::size_t i = 0; i < pass.tiles.size(); ++i) {
    sim::TileCounters& tile = pass.tiles[i];
    tile.triangle_refs = static_cast<std::uint32_t>(10 * i);
    tile.texture.dram_bytes = 640 * i;
    tile.color_load_bytes = 4096;
    tile.color_store_bytes = 4096;
    tile.depth_load_bytes = 3 * i;
    tile.depth_store_bytes = 7 * i;
  }
  sum_tiles(pass);
  const DramBytes d = estimate_pass(pass, p).dram;
  EXPECT_DOUBLE_EQ(d.parameter_write + d.parameter_read + d.texture + d.color_load + d.color_store +
                       d.depth_load + d.depth_store,
                   d.total());
  EXPECT_DOUBLE_EQ(d.texture, static_cast<double>(pass.texture.dram_bytes));
  EXPECT_DOUBLE_EQ(d.color_store, 6 * 4096.0);
  EXPECT_DOUBLE_EQ(d.depth_store, 7.0 * 15);
  EXPECT_GT(d.parameter_write, 0.0);
  EXPECT_GT(d.parameter_read, 0.0);
}

// MSAA resolved on chip: the samples never reach DRAM, so render-target bytes are those of
// 1x; with no tile-memory figure the tile holds one sample per pixel of the profile's tile,
// so 4 samples take 4 passes over the tile (PowerVR: 32x32 -> 16x16), each paying the
// per-tile cost and reading the tile's parameter-buffer list again.
TEST(PassCost, MsaaResolvedOnChipAddsTilePassesButNoRenderTargetBytes) {
  DeviceProfile p = round_profile();
  p.tile_memory_bytes.value = 32 * 32 * 9;  // the 1x tile exactly: 4x takes 4 passes
  const auto pass_with = [](int samples) {
    sim::PassCounters pass = make_pass(1, 1, 4);
    pass.samples = samples;
    pass.tile_bytes_per_sample = 4 + 5;  // RGBA8 + depth/stencil
    sim::TileCounters& tile = pass.tiles[0];
    tile.triangle_refs = 10;
    tile.color_store_bytes = 32 * 32 * 4;  // the resolved pixels, whatever the samples
    tile.fragments_depth_tested = 1024;
    sum_tiles(pass);
    return pass;
  };
  const sim::PassCounters one = pass_with(1), two = pass_with(2), four = pass_with(4);
  EXPECT_EQ(msaa_tile_passes(one, 0.0), 1);
  EXPECT_EQ(msaa_tile_passes(two, 0.0), 2);
  EXPECT_EQ(msaa_tile_passes(four, 0.0), 4);
  // A tile memory that holds 32x32 pixels x 4 samples x 9 bytes: one pass; a byte less: two.
  EXPECT_EQ(msaa_tile_passes(four, 32 * 32 * 4 * 9.0), 1);
  EXPECT_EQ(msaa_tile_passes(four, 32 * 32 * 4 * 9.0 - 1), 2);

  const PassTiming t1 = estimate_pass(one, p), t4 = estimate_pass(four, p);
  EXPECT_DOUBLE_EQ(t4.dram.color_store, t1.dram.color_store);
  EXPECT_DOUBLE_EQ(t4.dram.color_load + t4.dram.depth_load + t4.dram.depth_store, 0.0);
  EXPECT_DOUBLE_EQ(t4.dram.texture, t1.dram.texture);
  EXPECT_DOUBLE_EQ(t4.dram.parameter_read, 4 * t1.dram.parameter_read);
  EXPECT_DOUBLE_EQ(t4.tiles[0].isp_cycles, t1.tiles[0].isp_cycles);
  EXPECT_DOUBLE_EQ(t1.tiles[0].ms - 32 / kCyclesPerMs, t4.tiles[0].ms - 4 * 32 / kCyclesPerMs);
}

TEST(TileSchedule, GreedyListScheduleWithDeterministicTies) {
  const TileSchedule s = list_schedule({1, 1, 1, 1, 3}, 2);
  EXPECT_EQ(s.core, (std::vector<int>{0, 1, 0, 1, 0}));
  EXPECT_EQ(s.start, (std::vector<double>{0, 0, 1, 1, 2}));
  EXPECT_DOUBLE_EQ(s.makespan, 5.0);
  EXPECT_EQ(s.core_busy, (std::vector<double>{5, 2}));
}

TEST(PassCost, OneHeavyTileShowsUpAsImbalance) {
  DeviceProfile p = round_profile();
  p.cores.value = 2;
  sim::PassCounters pass = make_pass(8, 1, 2);
  const auto draw = add_draw(pass, 10);
  shade(pass, 0, draw, 8000);                                     // 10000 ALU cycles
  for (std::size_t i = 1; i < 8; ++i) shade(pass, i, draw, 800);  // 1000 each
  sum_tiles(pass);
  const PassTiming t = estimate_pass(pass, p);
  EXPECT_EQ(t.tiles[0].core, 0);
  for (std::size_t i = 1; i < 8; ++i) EXPECT_EQ(t.tiles[i].core, 1) << i;
  EXPECT_DOUBLE_EQ(t.makespan_ms, 10032.0 / kCyclesPerMs);
  EXPECT_DOUBLE_EQ(t.core_busy_ms[1], 7 * 1032.0 / kCyclesPerMs);
  EXPECT_DOUBLE_EQ(t.balance, (10032.0 + 7 * 1032.0) / 2 / 10032.0);
  // The same work spread evenly would finish earlier.
  EXPECT_GT(t.makespan_ms, (busy(t, Unit::kAlu) * 2 + 8 * 32 / kCyclesPerMs) / 2);
}

// A pass mixing every unit, scaled by `fragments` per tile.
sim::PassCounters mixed_pass(std::uint64_t fragments) {
  sim::PassCounters pass = make_pass(4, 3, 4);
  const auto draw = add_draw(pass, 6);
  pass.draws[draw].fragment_profile.transcendental_ops = 2;
  pass.draws[draw].fragment_profile.texture_reads_dependent = 1;
  for (std::size_t i = 0; i < pass.tiles.size(); ++i) {
    shade(pass, i, draw, fragments * (1 + i % 3));
    sim::TileCounters& tile = pass.tiles[i];
    tile.fragments_depth_tested *= 3;
    tile.triangle_refs = 20;
    tile.texture.samples_by_filter[2] = tile.fragments_shaded;
    tile.texture.samples_dependent = tile.fragments_shaded;
    tile.texture.dram_bytes = 16 * tile.fragments_shaded;
    tile.color_store_bytes = 4096;
  }
  pass.vertices_shaded = 500;
  pass.triangles_in = 900;
  pass.triangles_binned = 800;
  sum_tiles(pass);
  return pass;
}

TEST(PassCost, MoreFragmentsNeverTakeLessTime) {
  const DeviceProfile p = round_profile();
  double previous = 0.0;
  for (std::uint64_t f : {0, 1, 10, 100, 500, 1000, 5000, 20000}) {
    const double ms = estimate_pass(mixed_pass(f), p).standalone_ms;
    EXPECT_GE(ms, previous) << f;
    previous = ms;
  }
  EXPECT_GT(previous, estimate_pass(mixed_pass(0), p).standalone_ms);
}

TEST(PassCost, HigherClockIsNeverSlower) {
  DeviceProfile p = round_profile();
  const sim::PassCounters pass = mixed_pass(1000);
  double previous = 1e300;
  for (double mhz : {50.0, 100.0, 200.0, 300.0, 600.0, 2000.0}) {
    p.clock_mhz.value = mhz;
    const double ms = estimate_pass(pass, p).standalone_ms;
    EXPECT_LE(ms, previous) << mhz;
    previous = ms;
  }
}

TEST(PassCost, MoreBandwidthIsNeverSlower) {
  DeviceProfile p = round_profile();
  const sim::PassCounters pass = mixed_pass(1000);
  double previous = 1e300;
  for (double gbs : {0.1, 0.5, 1.0, 4.0, 17.0, 100.0}) {
    p.dram_peak_gb_per_s.value = gbs;
    const double ms = estimate_pass(pass, p).standalone_ms;
    EXPECT_LE(ms, previous) << gbs;
    previous = ms;
  }
  p.dram_peak_gb_per_s.value = 0.1;
  EXPECT_EQ(estimate_pass(pass, p).bottleneck, Unit::kBandwidth);
}

// Counters come only from the emulator: inconsistent ones are a bug in skinsim (exit 3), not
// bad input (exit 2, UserError).
static_assert(!std::is_base_of_v<UserError, CounterError>);

std::string counter_error(const sim::PassCounters& pass, const DeviceProfile& p) {
  try {
    estimate_pass(pass, p);
  } catch (const CounterError& e) {
    return e.what();
  }
  return "";
}

TEST(PassCost, InconsistentCountersAreRejectedWithTheField) {
  const DeviceProfile p = round_profile();
  sim::PassCounters pass = mixed_pass(10);
  pass.name = "irradiance";
  EXPECT_EQ(counter_error(pass, p), "");

  sim::PassCounters cores = pass;
  cores.cores = 2;
  EXPECT_NE(counter_error(cores, p).find("cores 2"), std::string::npos);

  sim::PassCounters tile_size = pass;
  tile_size.tile_size = 16;
  EXPECT_NE(counter_error(tile_size, p).find("tile_size 16"), std::string::npos);

  sim::PassCounters grid = pass;
  grid.tiles.pop_back();
  EXPECT_NE(counter_error(grid, p).find("tiles_x * tiles_y"), std::string::npos);

  sim::PassCounters draw = pass;
  draw.tiles[3].shaded_by_draw[0].draw = 7;
  const std::string m = counter_error(draw, p);
  EXPECT_NE(m.find("'irradiance'"), std::string::npos) << m;
  EXPECT_NE(m.find("draw 7"), std::string::npos) << m;

  sim::PassCounters sums = pass;
  sums.color_store_bytes += 1;
  EXPECT_NE(counter_error(sums, p).find("color_store_bytes"), std::string::npos);

  sim::PassCounters mediump = pass;
  mediump.draws[0].fragment_profile.vector_ops_mediump = 7;  // of 6
  EXPECT_NE(counter_error(mediump, p).find("more mediump ops"), std::string::npos);
}

TEST(PassCost, MediumpOpsCostTheProfilesMediumpShare) {
  DeviceProfile p = round_profile();
  p.mediump_op_cost.value = 0.5;
  sim::PassCounters pass = make_pass(4, 4, 4);
  const auto draw = add_draw(pass, 10);
  pass.draws[draw].fragment_profile.vector_ops_mediump = 6;  // 4 highp + 6 x 0.5
  pass.draws[draw].fragment_profile.transcendental_ops = 2;  // at mediump: no FP16 rate
  pass.draws[draw].fragment_profile.transcendental_ops_mediump = 2;
  for (std::size_t i = 0; i < pass.tiles.size(); ++i) shade(pass, i, draw, 1024);
  sum_tiles(pass);
  const PassTiming t = estimate_pass(pass, p);
  const double cycles = 4 + 6 * 0.5 + 2 * p.transcendental_op_cycles.value;
  for (const TileTiming& tile : t.tiles) EXPECT_DOUBLE_EQ(tile.alu_cycles, 1024.0 * cycles / 8);
}

}  // namespace
}  // namespace skinsim::gpu_model
