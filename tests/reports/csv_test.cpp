// results.csv: header and rows.
#include <gtest/gtest.h>

#include <sstream>

#include "reports/csv_writer.h"
#include "reports/error.h"
#include "tests/reports/synthetic_sweep.h"
#include "tests/text_lines.h"

namespace skinsim::reports {
namespace {

using skinsim::testing::lines_of;

TEST(SweepCsv, HeaderListsKnobsTotalsPassesAndMetrics) {
  const std::vector<std::string> lines = lines_of(sweep_csv(testing::synthetic_sweep()));
  ASSERT_EQ(lines.size(), 17u);  // header + 16 configurations
  EXPECT_EQ(lines[0],
            "id,label,blur_iterations,device,lut,lut_format,resolution,scale,technique,"
            "frame_ms,frame_ms_low,frame_ms_high,fps,dram_bytes,energy_mj,energy_mj_low,"
            "energy_mj_high,irradiance.ms,irradiance.bottleneck,blur_h.ms,"
            "blur_h.bottleneck,blur_v.ms,blur_v.bottleneck,skin_shade.ms,skin_shade.bottleneck,"
            "eyes_background.ms,eyes_background.bottleneck,flip_skin,psnr_frame,psnr_skin,"
            "ssim_skin,visible_vs_reference,group,finest,knob_flip,knob_visible_px,knob_visible,"
            "best,vs_best_flip,vs_best_visible_px,vs_best_visible");
}

TEST(SweepCsv, RowsCarryTheValues) {
  results::SweepTable sweep;
  results::ConfigResult r;
  r.id = "a";
  r.label = "scale 0.5, \"big\" LUT";
  r.knobs = {{"scale", "0.5"}};
  r.frame_ms = 12.5;
  r.frame_ms_low = 11;
  r.frame_ms_high = 15;
  r.fps = 80;
  r.dram_bytes = 1e6;
  r.energy_mj = 0.25;
  r.energy_mj_low = 0.125;
  r.energy_mj_high = 0.5;
  r.passes = {
      {"shade", 10.0, "alu", {}}, {"blur", 1.25, "texture", {}}, {"blur", 1.25, "dram", {}}};
  r.quality = {{"flip_skin", 0.125}};
  results::ConfigResult s;
  s.id = "b";
  s.frame_ms = 3;
  s.frame_ms_low = 3;
  s.frame_ms_high = 3;
  s.fps = 333;
  sweep.rows = {r, s};
  const std::vector<std::string> lines = lines_of(sweep_csv(sweep));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0],
            "id,label,scale,frame_ms,frame_ms_low,frame_ms_high,fps,dram_bytes,energy_mj,"
            "energy_mj_low,energy_mj_high,shade.ms,shade.bottleneck,blur.ms,"
            "blur.bottleneck,flip_skin,visible_vs_reference,group,finest,knob_flip,knob_visible_px,"
            "knob_visible,best,vs_best_flip,vs_best_visible_px,vs_best_visible");
  EXPECT_EQ(lines[1],
            "a,\"scale 0.5, \"\"big\"\" LUT\",0.5,12.5,11,15,80,1000000,0.25,0.125,0.5,10,alu,2.5,"
            "texture,0.125,"
            ",,,,,,,,,");
  EXPECT_EQ(lines[2], "b,,,3,3,3,333,0,0,0,0,,,,,,,,,,,,,,,");
}

TEST(SweepCsv, CollidingColumnNamesAreAnError) {
  results::SweepTable sweep;
  results::ConfigResult r;
  r.id = "a";
  r.knobs = {{"flip_skin", "x"}};
  r.quality = {{"flip_skin", 0.1}};
  sweep.rows = {r};
  EXPECT_THROW(sweep_csv(sweep), ReportError);
}

TEST(CsvField, QuotesOnlyWhenNeeded) {
  EXPECT_EQ(csv_field("plain"), "plain");
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("line\nbreak"), "\"line\nbreak\"");
}

}  // namespace
}  // namespace skinsim::reports
