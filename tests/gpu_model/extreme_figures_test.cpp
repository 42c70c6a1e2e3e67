// Every profile figure at each of its bounds (FigureSpec), one at a time and all together,
// on a heavy and an empty pass: the model's times, bytes and ratios stay finite.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gpu_model/device_profile.h"
#include "gpu_model/frame_cost.h"
#include "gpu_model/timing.h"
#include "test_support.h"

namespace skinsim::gpu_model {
namespace {

// Counters as large as a frame of the emulator can plausibly produce, for the profile's tile
// size and core count.
sim::PassCounters heavy_pass(const DeviceProfile& p) {
  sim::PassCounters pass = testing::make_pass(8, 8, static_cast<int>(p.cores.value));
  pass.tile_size = static_cast<int>(p.tile_width.value);
  const std::uint32_t draw = testing::add_draw(pass, 1000);
  pass.draws[draw].vertices_shaded = 1'000'000'000;
  pass.draws[draw].vertex_profile.transcendental_ops = 1000;
  pass.draws[draw].fragment_profile.transcendental_ops = 1000;
  pass.vertices_shaded = pass.triangles_in = pass.triangles_binned = 1'000'000'000;
  pass.varying_floats_per_vertex = 64;
  for (std::size_t i = 0; i < pass.tiles.size(); ++i) {
    testing::shade(pass, i, draw, 1'000'000'000);
    sim::TileCounters& t = pass.tiles[i];
    t.triangle_refs = 1'000'000'000;
    t.fragments_blended = t.fragments_shaded;
    t.hsr_flushes = 1'000'000;
    t.texture.samples_by_filter[2] = 1'000'000'000;
    t.texture.samples_dependent = t.texture.samples_wide_format = 1'000'000'000;
    t.texture.dram_bytes = 1'000'000'000'000;
    t.color_load_bytes = t.color_store_bytes = t.depth_load_bytes = t.depth_store_bytes =
        1'000'000'000;
  }
  testing::sum_tiles(pass);
  return pass;
}

sim::PassCounters empty_pass(const DeviceProfile& p) {
  sim::PassCounters pass = testing::make_pass(2, 2, static_cast<int>(p.cores.value));
  pass.tile_size = static_cast<int>(p.tile_width.value);
  return pass;
}

void expect_finite(const FrameTiming& f, const std::string& what) {
  EXPECT_TRUE(std::isfinite(f.frame_ms) && f.frame_ms >= 0.0) << what << ": " << f.frame_ms;
  EXPECT_TRUE(std::isfinite(f.fps)) << what;
  EXPECT_TRUE(std::isfinite(f.dram_bytes)) << what;
  for (const PassTiming& t : f.passes) {
    EXPECT_TRUE(std::isfinite(t.standalone_ms) && std::isfinite(t.ta_ms) &&
                std::isfinite(t.render_ms))
        << what;
    for (double u : t.utilisation) EXPECT_TRUE(std::isfinite(u)) << what;
  }
}

void expect_finite_frames(const DeviceProfile& p, const std::string& what) {
  expect_finite(estimate_frame({heavy_pass(p), empty_pass(p)}, p), what + ", heavy");
  expect_finite(estimate_frame({empty_pass(p)}, p), what + ", empty");
}

// Square tiles: the two tile axes move together (the loader requires it).
void set_value(DeviceProfile& p, const FigureSpec& spec, double v) {
  (p.*spec.member).value = v;
  if (spec.member == &DeviceProfile::tile_width) p.tile_height.value = v;
  if (spec.member == &DeviceProfile::tile_height) p.tile_width.value = v;
}

TEST(ExtremeFigures, EachFigureAtEachBoundGivesFiniteTimes) {
  const DeviceProfile base = testing::round_profile();
  for (const FigureSpec& spec : figure_specs()) {
    for (double bound : {spec.bounds.min, spec.bounds.max}) {
      DeviceProfile p = base;
      set_value(p, spec, bound);
      expect_finite_frames(p, std::string(spec.path) + " = " + std::to_string(bound));
    }
  }
}

TEST(ExtremeFigures, AllFiguresAtOneEndGiveFiniteTimes) {
  for (const bool at_max : {false, true}) {
    DeviceProfile p = testing::round_profile();
    for (const FigureSpec& spec : figure_specs()) {
      set_value(p, spec, at_max ? spec.bounds.max : spec.bounds.min);
    }
    expect_finite_frames(p, at_max ? "all at max" : "all at min");
  }
}

}  // namespace
}  // namespace skinsim::gpu_model
