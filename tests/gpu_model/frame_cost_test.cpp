#include "gpu_model/frame_cost.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "gpu_model/timing_json.h"
#include "gpu_model/timing_table.h"
#include "results/pass_rows.h"
#include "test_support.h"

namespace skinsim::gpu_model {
namespace {

using testing::add_draw;
using testing::make_pass;
using testing::round_profile;
using testing::shade;
using testing::sum_tiles;

PassTiming stage_times(double ta_ms, double render_ms) {
  PassTiming t;
  t.ta_ms = ta_ms;
  t.render_ms = render_ms;
  return t;
}

TEST(FrameCost, TilerOfNextPassOverlapsRendererOfThisOne) {
  // (TA, 3D): (2, 5), (4, 1), (1, 1).
  // Pass 0: TA 0-2, 3D 2-7. Pass 1: TA 2-6 (3D of pass 0 started at 2), 3D 7-8.
  // Pass 2: TA waits for 3D of pass 1 to start (7), runs 7-8; 3D 8-9.
  const auto slots = pipeline_schedule({stage_times(2, 5), stage_times(4, 1), stage_times(1, 1)});
  ASSERT_EQ(slots.size(), 3u);
  EXPECT_DOUBLE_EQ(slots[0].render_start_ms, 2);
  EXPECT_DOUBLE_EQ(slots[0].render_end_ms, 7);
  EXPECT_DOUBLE_EQ(slots[1].ta_start_ms, 2);
  EXPECT_DOUBLE_EQ(slots[1].ta_end_ms, 6);
  EXPECT_DOUBLE_EQ(slots[1].render_start_ms, 7);
  EXPECT_DOUBLE_EQ(slots[2].ta_start_ms, 7);
  EXPECT_DOUBLE_EQ(slots[2].render_end_ms, 9);
  EXPECT_DOUBLE_EQ(slots[0].exposed_ms + slots[1].exposed_ms + slots[2].exposed_ms, 9);
  EXPECT_DOUBLE_EQ(slots[1].exposed_ms, 1);
}

TEST(FrameCost, TilerBoundPassesSerialiseOnTheTiler) {
  const auto slots = pipeline_schedule({stage_times(3, 1), stage_times(3, 1)});
  EXPECT_DOUBLE_EQ(slots[1].ta_start_ms, 3);
  EXPECT_DOUBLE_EQ(slots[1].render_end_ms, 7);
}

std::vector<sim::PassCounters> two_passes() {
  sim::PassCounters a = make_pass(4, 4, 4);
  a.name = "irradiance";
  const auto da = add_draw(a, 12);
  for (std::size_t i = 0; i < a.tiles.size(); ++i) {
    shade(a, i, da, 900);
    a.tiles[i].triangle_refs = 30;
    a.tiles[i].color_store_bytes = 4096;
    a.tiles[i].texture.samples_by_filter[1] = 900;
    a.tiles[i].texture.dram_bytes = 2048;
  }
  a.vertices_shaded = 5000;
  a.triangles_in = 9000;
  a.triangles_binned = 4000;
  a.varying_floats_per_vertex = 10;
  sum_tiles(a);

  sim::PassCounters b = make_pass(4, 4, 4);
  b.name = "composite";
  const auto db = add_draw(b, 4);
  for (std::size_t i = 0; i < b.tiles.size(); ++i) {
    shade(b, i, db, 1024);
    b.tiles[i].triangle_refs = 2;
    b.tiles[i].color_store_bytes = 4096;
    b.tiles[i].color_load_bytes = 4096;
  }
  b.vertices_shaded = 4;
  b.triangles_in = 2;
  b.triangles_binned = 2;
  sum_tiles(b);
  return {a, b};
}

TEST(FrameCost, FrameBytesAreTheSumOfPassBytes) {
  const FrameTiming f = estimate_frame(two_passes(), round_profile());
  ASSERT_EQ(f.passes.size(), 2u);
  EXPECT_DOUBLE_EQ(f.dram_bytes, f.passes[0].dram.total() + f.passes[1].dram.total());
  EXPECT_DOUBLE_EQ(f.dram.color_load, f.passes[1].dram.color_load);
  EXPECT_DOUBLE_EQ(f.dram.total(), f.dram_bytes);
  EXPECT_DOUBLE_EQ(f.frame_ms, std::max(f.pipeline_ms, f.bandwidth_ms));
  EXPECT_DOUBLE_EQ(f.fps, 1000.0 / f.frame_ms);
  // Overlap: the frame is shorter than the stages in sequence and no shorter than the 3D work.
  const double serial =
      f.passes[0].ta_ms + f.passes[0].render_ms + f.passes[1].ta_ms + f.passes[1].render_ms;
  EXPECT_LT(f.frame_ms, serial);
  EXPECT_GE(f.frame_ms, f.passes[0].render_ms + f.passes[1].render_ms);
}

TEST(FrameCost, OverlappedStagesShareTheDram) {
  // Pass A's renderer streams textures while pass B's tiler writes its parameter buffer; the
  // stages overlap in the pipeline, but not in the one DRAM.
  DeviceProfile p = round_profile();
  p.render_overhead_cycles.value = 0.0;
  sim::PassCounters a = make_pass(1, 1, 4);
  a.tiles[0].texture.samples_by_filter[1] = 1;
  a.tiles[0].texture.dram_bytes = 10'000'000;
  sum_tiles(a);
  sim::PassCounters b = make_pass(1, 1, 4);
  b.vertices_shaded = 500'000;  // 16 B each: 8 MB of parameter buffer
  b.tiles[0].color_store_bytes = 4096;
  sum_tiles(b);

  const FrameTiming f = estimate_frame({a, b}, p);
  EXPECT_DOUBLE_EQ(f.schedule[1].ta_start_ms, 0.0);  // B's TA overlaps A's render
  const double bytes_per_ms = 17.06 * 0.6 * 1e6;
  EXPECT_DOUBLE_EQ(f.bandwidth_ms, (10'000'000.0 + 8'000'000.0 + 4096.0) / bytes_per_ms);
  EXPECT_GT(f.bandwidth_ms, f.pipeline_ms);
  EXPECT_DOUBLE_EQ(f.frame_ms, f.bandwidth_ms);
  // The passes' ms (their shares of the pipeline) and the DRAM wait add up to the frame, in
  // the struct, the table and the JSON.
  EXPECT_DOUBLE_EQ(f.dram_wait_ms, f.bandwidth_ms - f.pipeline_ms);
  EXPECT_NEAR(f.schedule[0].exposed_ms + f.schedule[1].exposed_ms + f.dram_wait_ms, f.frame_ms,
              1e-12);
  EXPECT_NE(format_frame_table(f).find(
                fmt::format("{:<24} {:>8.3f}", results::kDramWaitRow, f.dram_wait_ms)),
            std::string::npos)
      << format_frame_table(f);
  EXPECT_DOUBLE_EQ(to_json(f)["dram_wait_ms"].get<double>(), f.dram_wait_ms);
}

TEST(FrameCost, PipelineBoundFrameHasNoDramWaitRow) {
  const FrameTiming f = estimate_frame(two_passes(), round_profile());
  ASSERT_GE(f.pipeline_ms, f.bandwidth_ms);
  EXPECT_DOUBLE_EQ(f.dram_wait_ms, 0.0);
  EXPECT_EQ(format_frame_table(f).find(results::kDramWaitRow), std::string::npos);
}

TEST(FrameCost, JsonCarriesPassesAndFrameTotals) {
  const FrameTiming f = estimate_frame(two_passes(), round_profile());
  const nlohmann::json j = to_json(f);
  EXPECT_EQ(j["device"], "ipad4");
  EXPECT_DOUBLE_EQ(j["frame_ms"].get<double>(), f.frame_ms);
  EXPECT_DOUBLE_EQ(j["dram_bytes"]["total"].get<double>(), f.dram_bytes);
  ASSERT_EQ(j["passes"].size(), 2u);
  const auto& pass = j["passes"][0];
  EXPECT_EQ(pass["name"], "irradiance");
  EXPECT_EQ(pass["bottleneck"], unit_name(f.passes[0].bottleneck));
  EXPECT_DOUBLE_EQ(pass["ms"].get<double>(), f.schedule[0].exposed_ms);
  EXPECT_DOUBLE_EQ(pass["standalone_ms"].get<double>(), f.passes[0].standalone_ms);
  for (const char* unit : {"alu", "texture", "isp", "bandwidth", "tiler", "overhead"}) {
    EXPECT_TRUE(pass["utilisation"].contains(unit)) << unit;
  }
  double causes = 0.0;
  for (const char* cause : {"parameter_write", "parameter_read", "texture", "color_load",
                            "color_store", "depth_load", "depth_store"}) {
    causes += pass["dram_bytes"][cause].get<double>();
  }
  EXPECT_DOUBLE_EQ(causes, pass["dram_bytes"]["total"].get<double>());
  const nlohmann::json tiles = tiles_to_json(f.passes[0]);
  ASSERT_EQ(tiles.size(), 16u);
  EXPECT_EQ(tiles[5]["x"], 1);
  EXPECT_EQ(tiles[5]["y"], 1);
}

TEST(FrameCost, TableNamesEveryPassAndTheTotal) {
  const FrameTiming f = estimate_frame(two_passes(), round_profile());
  const std::string table = format_frame_table(f);
  EXPECT_NE(table.find("irradiance"), std::string::npos) << table;
  EXPECT_NE(table.find("composite"), std::string::npos) << table;
  EXPECT_NE(table.find(fmt::format("{:.3f}", f.frame_ms)), std::string::npos) << table;
}

TEST(FrameCost, EmptyFrameTakesNoTime) {
  const FrameTiming f = estimate_frame({}, round_profile());
  EXPECT_DOUBLE_EQ(f.frame_ms, 0.0);
  EXPECT_DOUBLE_EQ(f.fps, 0.0);
}

}  // namespace
}  // namespace skinsim::gpu_model
