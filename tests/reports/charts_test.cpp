// Chart functions draw real, non-blank images of the requested size (needs an X display:
// registered under xvfb-run).
#include "reports/charts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "image/image.h"
#include "reports/display_check.h"
#include "reports/error.h"
#include "reports/palette.h"
#include "reports/report_charts.h"
#include "reports/sequence_charts.h"
#include "results/pass_rows.h"
#include "tests/reports/synthetic_sweep.h"
#include "tests/reports/test_output_dir.h"

namespace skinsim::reports {
namespace {

namespace fs = std::filesystem;
using testing::fresh_output_dir;
using testing::synthetic_sweep;

class ChartsTest : public ::testing::Test {
 protected:
  // Skipped only where there is no display to use; a display that is named (CTest runs these
  // under xvfb-run where it is installed) but cannot draw the charts is a failure.
  void SetUp() override {
    std::string why;
    if (charts_available(&why)) return;
    if (std::getenv("DISPLAY")) FAIL() << why;
    GTEST_SKIP() << why;
  }
  ChartOptions options_;
};

// The PNG has the requested size and more than one colour; the SVG is non-empty vector text.
void expect_real_chart(const ChartFiles& files, const ChartOptions& options) {
  ASSERT_TRUE(fs::exists(files.png)) << files.png;
  const image::Image image = image::load_png(files.png);
  EXPECT_EQ(image.width, options.width);
  EXPECT_EQ(image.height, options.height);
  const bool varies = std::any_of(image.rgb.begin(), image.rgb.end(),
                                  [&](const glm::vec3& p) { return p != image.rgb.front(); });
  EXPECT_TRUE(varies) << files.png << " is a single colour";
  if (!files.svg.empty()) {
    ASSERT_TRUE(fs::exists(files.svg)) << files.svg;
    EXPECT_GT(fs::file_size(files.svg), 1000u);
  }
}

TEST_F(ChartsTest, TradeoffChartPerLutAndPerScale) {
  const std::string dir = fresh_output_dir();
  const results::SweepTable sweep = synthetic_sweep();
  TradeoffSpec by_lut;
  by_lut.metric_label = "FLIP mean over skin (lower is better)";
  expect_real_chart(write_tradeoff_chart(sweep, by_lut, dir + "/tradeoff_by_lut", options_),
                    options_);
  TradeoffSpec by_scale = by_lut;
  by_scale.series_knob = "scale";
  by_scale.order_knob = "lut";
  expect_real_chart(write_tradeoff_chart(sweep, by_scale, dir + "/tradeoff_by_scale", options_),
                    options_);
  TradeoffSpec ssim;
  ssim.metric = "ssim_skin";
  ssim.higher_is_better = true;
  options_.write_svg = false;
  const ChartFiles png_only = write_tradeoff_chart(sweep, ssim, dir + "/tradeoff_ssim", options_);
  expect_real_chart(png_only, options_);
  EXPECT_TRUE(png_only.svg.empty());
  EXPECT_FALSE(fs::exists(dir + "/tradeoff_ssim.svg"));
}

TEST_F(ChartsTest, TradeoffChartComparesTechniques) {
  results::SweepTable sweep = synthetic_sweep();
  for (std::size_t i = 0; i < sweep.rows.size(); i += 2) {
    sweep.rows[i].knobs["technique"] = "preintegrated";
  }
  TradeoffSpec spec;
  spec.series_knob = "technique";
  spec.order_knob = "";
  spec.filter = {{"scale", "0.5"}};  // the knob filter keeps 4 rows, 2 per technique
  options_.write_svg = false;
  expect_real_chart(write_tradeoff_chart(sweep, spec, fresh_output_dir() + "/techniques", options_),
                    options_);
}

// A technique that ignores the scale has no scale in its rows (the sweep leaves it out).
results::SweepTable with_scale_free_rows() {
  results::SweepTable sweep = synthetic_sweep();
  for (std::size_t i = 0; i < 4; ++i) {
    results::ConfigResult r = sweep.rows[i];
    r.id += "_wrap";
    r.knobs["technique"] = "wrap";
    r.knobs.erase("scale");
    r.frame_ms = 5.0;  // the cheapest rows, so the recommended one is off the scale charts
    r.frame_ms_low = 4.5;
    r.frame_ms_high = 7.0;
    sweep.rows.push_back(r);
  }
  return sweep;
}

TEST(TradeoffRows, ARowIsOnAChartOnlyWithItsSeriesAndOrderKnobs) {
  const results::SweepTable sweep = with_scale_free_rows();
  TradeoffSpec by_lut;  // series lut, ordered by scale
  TradeoffSpec by_technique;
  by_technique.series_knob = "technique";
  by_technique.order_knob = "";
  EXPECT_TRUE(on_tradeoff_chart(sweep.rows.front(), by_lut));
  EXPECT_FALSE(on_tradeoff_chart(sweep.rows.back(), by_lut));
  EXPECT_TRUE(on_tradeoff_chart(sweep.rows.back(), by_technique));
}

// A knob swept over one value gets no chart of its own: its one line across the other knob
// would repeat that knob's chart under the wrong name.
TEST(TradeoffRows, AKnobSweptOverOneValueGetsNoChart) {
  results::SweepTable sweep = synthetic_sweep();
  TradeoffSpec by_lut;  // series lut, ordered by scale
  TradeoffSpec by_scale;
  by_scale.series_knob = "scale";
  by_scale.order_knob = "lut";
  TradeoffSpec by_technique;
  by_technique.series_knob = "technique";
  by_technique.order_knob = "";
  EXPECT_TRUE(tradeoff_chart_worth_drawing(sweep, by_lut));
  EXPECT_TRUE(tradeoff_chart_worth_drawing(sweep, by_scale));
  EXPECT_FALSE(tradeoff_chart_worth_drawing(sweep, by_technique));
  std::erase_if(sweep.rows, [](const results::ConfigResult& r) {
    return results::knob_value(r, "lut") != "32x128";  // the scales of one LUT size
  });
  EXPECT_FALSE(tradeoff_chart_worth_drawing(sweep, by_lut));
  EXPECT_TRUE(tradeoff_chart_worth_drawing(sweep, by_scale));
}

// A bottleneck map of one colour says nothing the cost map's caption cannot: not drawn.
TEST(TileMaps, OneUnitOverEveryTileIsNamedNotDrawn) {
  results::TileHeatmap heatmap = testing::synthetic_heatmap();
  EXPECT_EQ(single_tile_bottleneck(heatmap), std::nullopt);  // dram, alu and texture tiles
  std::fill(heatmap.bottleneck.begin(), heatmap.bottleneck.end(), "texture");
  EXPECT_EQ(single_tile_bottleneck(heatmap), "texture");
  heatmap.bottleneck.clear();
  EXPECT_EQ(single_tile_bottleneck(heatmap), std::nullopt);
}

TEST_F(ChartsTest, TradeoffChartLeavesOutRowsWithoutItsKnobs) {
  const results::SweepTable sweep = with_scale_free_rows();
  options_.write_svg = false;
  TradeoffSpec by_lut;
  expect_real_chart(write_tradeoff_chart(sweep, by_lut, fresh_output_dir() + "/lut", options_),
                    options_);
  TradeoffSpec only_wrap = by_lut;
  only_wrap.filter = {{"technique", "wrap"}};  // every such row lacks the scale
  EXPECT_THROW(write_tradeoff_chart(sweep, only_wrap, fresh_output_dir() + "/x", options_),
               ReportError);
}

TEST_F(ChartsTest, TradeoffChartHonoursRequestedSize) {
  const std::string dir = fresh_output_dir();
  options_.width = 900;
  options_.height = 600;
  options_.write_svg = false;
  expect_real_chart(write_tradeoff_chart(synthetic_sweep(), {}, dir + "/small", options_),
                    options_);
}

TEST_F(ChartsTest, TradeoffChartWithoutTheMetricThrows) {
  TradeoffSpec spec;
  spec.metric = "no_such_metric";
  EXPECT_THROW(write_tradeoff_chart(synthetic_sweep(), spec, fresh_output_dir() + "/x", options_),
               ReportError);
}

TEST_F(ChartsTest, EnergyChartPerDeviceGroup) {
  results::SweepTable sweep = synthetic_sweep();
  for (std::size_t i = 0; i < sweep.rows.size(); ++i) {
    sweep.rows[i].group = i % 2 ? "a15, 2048x1536" : "ipad4, 2048x1536";
  }
  const std::string dir = fresh_output_dir();
  expect_real_chart(write_energy_chart(sweep, {"flip_skin", false, "FLIP (lower is better)"},
                                       dir + "/energy", options_),
                    options_);
  // Every configuration at the same energy (a zero-width axis) still draws.
  for (results::ConfigResult& r : sweep.rows)
    r.energy_mj = r.energy_mj_low = r.energy_mj_high = 0.0;
  options_.write_svg = false;
  expect_real_chart(
      write_energy_chart(sweep, {"flip_skin", false, "FLIP"}, dir + "/flat", options_), options_);
}

TEST_F(ChartsTest, EnergyChartWithoutTheMetricThrows) {
  EXPECT_THROW(write_energy_chart(synthetic_sweep(), {"no_such_metric", false, "x"},
                                  fresh_output_dir() + "/x", options_),
               ReportError);
}

TEST_F(ChartsTest, PassStackChart) {
  const std::string dir = fresh_output_dir();
  const ChartFiles files = write_pass_stack_chart(synthetic_sweep(), dir + "/passes", options_);
  EXPECT_FALSE(files.svg.empty());
  expect_real_chart(files, options_);
}

TEST_F(ChartsTest, TileHeatmapAndBottleneckMap) {
  const std::string dir = fresh_output_dir();
  const results::TileHeatmap heatmap = *synthetic_sweep().heatmap;
  const ChartFiles cost = write_tile_cost_heatmap(heatmap, dir + "/tile_cost", options_);
  EXPECT_TRUE(cost.svg.empty());  // raster content: PNG only
  expect_real_chart(cost, options_);
  expect_real_chart(write_tile_bottleneck_map(heatmap, dir + "/tile_bottleneck", options_),
                    options_);
}

TEST_F(ChartsTest, BottleneckMapNeedsBottlenecks) {
  results::TileHeatmap heatmap = *synthetic_sweep().heatmap;
  heatmap.bottleneck.clear();
  EXPECT_THROW(write_tile_bottleneck_map(heatmap, fresh_output_dir() + "/x", options_),
               ReportError);
}

TEST_F(ChartsTest, DramByCauseChart) {
  const std::string dir = fresh_output_dir();
  expect_real_chart(write_dram_by_cause_chart(synthetic_sweep().rows[5], dir + "/dram", options_),
                    options_);
}

// A push-in like sequence: the LOD shader switching off at frame 4, then closer frames.
SequenceSeries synthetic_sequence() {
  SequenceSeries s;
  s.title = "synthetic";
  s.pass_names = {"shadow", "skin"};
  s.pass_ms.assign(2, {});
  for (int i = 0; i < 10; ++i) {
    const double skin = i < 4 ? 2.0 : 5.0 + i;
    s.time_s.push_back(i / 30.0);
    s.pass_ms[0].push_back(1.0);
    s.pass_ms[1].push_back(skin);
    s.frame_ms.push_back(1.0 + skin);
    s.low_ms.push_back(0.8 * (1.0 + skin));
    s.high_ms.push_back(1.5 * (1.0 + skin));
    s.quality.push_back(0.05 + 0.002 * i);
    if (i > 0) s.temporal_error.push_back(i == 4 ? 0.02 : 0.001);  // the LOD pop
  }
  s.quality_label = "flip_skin";
  s.budget_ms = 16.7;
  return s;
}

TEST_F(ChartsTest, SequenceFrameTimeAndPassStack) {
  const std::string dir = fresh_output_dir();
  const SequenceSeries s = synthetic_sequence();
  expect_real_chart(write_sequence_frame_chart(s, dir + "/frame_ms", options_), options_);
  expect_real_chart(write_sequence_pass_chart(s, dir + "/passes", options_), options_);
  expect_real_chart(write_sequence_quality_chart(s, dir + "/quality", options_), options_);
}

TEST_F(ChartsTest, EmptySequenceIsAReportError) {
  const std::string dir = fresh_output_dir();
  EXPECT_THROW(write_sequence_frame_chart(SequenceSeries{}, dir + "/f", options_), ReportError);
  SequenceSeries no_passes = synthetic_sequence();
  no_passes.pass_names.clear();
  EXPECT_THROW(write_sequence_pass_chart(no_passes, dir + "/p", options_), ReportError);
  SequenceSeries no_quality = synthetic_sequence();
  no_quality.quality.clear();
  EXPECT_THROW(write_sequence_quality_chart(no_quality, dir + "/q", options_), ReportError);
}

// Every pass of a --techniques sweep (25 and the DRAM wait) has a colour of its own, far
// enough (in RGB) from the others to be told apart in a stacked bar and its legend.
TEST(PassColour, EveryPassOfAWideSweepHasItsOwnColour) {
  for (std::size_t passes : {4u, 10u, 11u, 25u}) {
    std::vector<std::string> order;
    for (std::size_t i = 0; i < passes; ++i) order.push_back("pass" + std::to_string(i));
    order.insert(order.begin() + 2, results::kDramWaitRow);
    for (std::size_t a = 0; a < order.size(); ++a) {
      for (std::size_t b = a + 1; b < order.size(); ++b) {
        const Rgb ca = pass_colour(order[a], order), cb = pass_colour(order[b], order);
        double squared = 0.0;
        for (int k = 0; k < 3; ++k) squared += std::pow(static_cast<double>(ca[k]) - cb[k], 2.0);
        EXPECT_GE(std::sqrt(squared), 40.0)
            << order[a] << " and " << order[b] << " of " << passes << " passes";
      }
    }
  }
}

TEST(BudgetLabel, NamesMillisecondsAndFps) {
  EXPECT_EQ(budget_label(33.3), "33.3 ms (30 fps)");
  EXPECT_EQ(budget_label(16.7), "16.7 ms (60 fps)");
}

}  // namespace
}  // namespace skinsim::reports
