#include "gpu_model/sensitivity.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "gpu_model/frame_cost.h"
#include "gpu_model/timing_json.h"
#include "gpu_model/timing_table.h"
#include "test_support.h"

namespace skinsim::gpu_model {
namespace {

using testing::add_draw;
using testing::make_pass;
using testing::shade;
using testing::sum_tiles;

// A texture-heavy pass whose misses scale inversely with the texture cache size, standing in
// for an emulator re-run.
sim::PassCounters pass_for_cache(double cache_bytes) {
  sim::PassCounters pass = make_pass(8, 6, 4);
  const auto draw = add_draw(pass, 8);
  for (std::size_t i = 0; i < pass.tiles.size(); ++i) {
    shade(pass, i, draw, 1024);
    sim::TileCounters& tile = pass.tiles[i];
    tile.texture.samples_by_filter[2] = 2048;
    tile.texture.dram_bytes = static_cast<std::uint64_t>(64 * 8192 * 4096.0 / cache_bytes);
    tile.color_store_bytes = 4096;
    tile.triangle_refs = 10;
  }
  pass.vertices_shaded = 2000;
  pass.triangles_in = 4000;
  pass.triangles_binned = 3000;
  sum_tiles(pass);
  return pass;
}

const SensitivityRow& row(const std::vector<SensitivityRow>& rows, const std::string& figure) {
  const auto it = std::find_if(rows.begin(), rows.end(),
                               [&](const SensitivityRow& r) { return r.figure == figure; });
  EXPECT_NE(it, rows.end()) << figure;
  return *it;
}

TEST(Sensitivity, OneRowPerRangedFigureWithFrameTimesAtTheEnds) {
  const DeviceProfile p = load_device_profile("ipad4", testing::kDataDir);
  const std::vector<sim::PassCounters> passes = {pass_for_cache(8192)};
  const auto rows = sensitivity(passes, p);
  std::size_t ranged = 0;
  // Energy and tile-memory figures have ranges but no effect on time: no rows.
  for (const FigureSpec& spec : figure_specs()) {
    ranged += (p.*spec.member).has_range && spec.timed ? 1 : 0;
  }
  EXPECT_EQ(rows.size(), ranged);
  ASSERT_TRUE(p.dram_pj_per_byte.has_range);
  for (const SensitivityRow& r : rows) EXPECT_NE(r.figure.rfind("energy.", 0), 0u) << r.figure;

  const double base = estimate_frame(passes, p).frame_ms;
  const SensitivityRow& clock = row(rows, "gpu.clock_mhz");
  EXPECT_DOUBLE_EQ(clock.frame_ms_base, base);
  EXPECT_DOUBLE_EQ(clock.value_min, 280.0);
  ASSERT_TRUE(clock.frame_ms_min && clock.frame_ms_max);
  EXPECT_GT(*clock.frame_ms_min, base);  // slower clock, longer frame
  EXPECT_DOUBLE_EQ(*clock.frame_ms_max, base);

  const SensitivityRow& fraction = row(rows, "memory.achievable_fraction");
  ASSERT_TRUE(fraction.frame_ms_min && fraction.frame_ms_max);
  EXPECT_GE(*fraction.frame_ms_min, base);
  EXPECT_LE(*fraction.frame_ms_max, base);

  const SensitivityRow& cache = row(rows, "texture.cache_bytes");
  EXPECT_TRUE(cache.needs_recount);
  EXPECT_FALSE(cache.frame_ms_min.has_value());
  EXPECT_FALSE(cache.frame_ms_max.has_value());

  const std::string table = format_sensitivity_table(rows);
  EXPECT_NE(table.find("gpu.clock_mhz"), std::string::npos) << table;
  EXPECT_NE(table.find("re-run"), std::string::npos) << table;
  EXPECT_EQ(to_json(rows).size(), rows.size());
}

TEST(Sensitivity, CacheFiguresUseTheRecountHook) {
  const DeviceProfile p = load_device_profile("ipad4", testing::kDataDir);
  int calls = 0;
  const Recount recount = [&](const DeviceProfile& varied) {
    ++calls;
    return std::vector<sim::PassCounters>{pass_for_cache(varied.texture_cache_bytes.value)};
  };
  const auto rows = sensitivity({pass_for_cache(8192)}, p, recount);
  // One re-run per range endpoint of a counter-affecting figure, except an endpoint equal to
  // the figure's value (e.g. texture.cache_set_hash 0 in [0, 1]): that is the base frame.
  int affecting = 0;
  for (const FigureSpec& spec : figure_specs()) {
    const Figure& f = p.*spec.member;
    if (!spec.affects_counters || !f.has_range) continue;
    affecting += (f.min != f.value ? 1 : 0) + (f.max != f.value ? 1 : 0);
  }
  EXPECT_EQ(calls, affecting);
  const SensitivityRow& hash = row(rows, "texture.cache_set_hash");
  ASSERT_TRUE(hash.frame_ms_min);
  EXPECT_EQ(*hash.frame_ms_min, hash.frame_ms_base);
  const SensitivityRow& cache = row(rows, "texture.cache_bytes");
  ASSERT_TRUE(cache.frame_ms_min && cache.frame_ms_max);
  EXPECT_GT(*cache.frame_ms_min, cache.frame_ms_base);  // smaller cache, more misses
  EXPECT_LT(*cache.frame_ms_max, cache.frame_ms_base);
}

// Each row is the frame estimated with only its figure moved to each end, the others at
// their values: estimated here from a profile varied by hand, so a row that kept an earlier
// row's change, or moved another figure, differs.
TEST(Sensitivity, EachRowMovesOnlyItsFigure) {
  const DeviceProfile p = load_device_profile("ipad3", testing::kDataDir);
  const std::vector<sim::PassCounters> passes = {pass_for_cache(8192)};
  const auto rows = sensitivity(passes, p);
  std::size_t i = 0;
  for (const FigureSpec& spec : figure_specs()) {
    const Figure& f = p.*spec.member;
    if (!f.has_range || !spec.timed) continue;
    ASSERT_LT(i, rows.size());
    const SensitivityRow& r = rows[i++];
    EXPECT_EQ(r.figure, spec.path);
    if (spec.affects_counters) continue;  // no recount given: base time only
    for (const auto& [value, ms] : {std::pair{f.min, r.frame_ms_min}, {f.max, r.frame_ms_max}}) {
      DeviceProfile varied = p;
      (varied.*spec.member).value = value;
      ASSERT_TRUE(ms) << r.figure;
      EXPECT_DOUBLE_EQ(*ms, estimate_frame(passes, varied).frame_ms) << r.figure << " = " << value;
    }
  }
  EXPECT_EQ(i, rows.size());
}

}  // namespace
}  // namespace skinsim::gpu_model
