// results.json round trip and the errors bad input gets.
#include "reports/sweep_json.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/read_file.h"
#include "results/error.h"
#include "results/sweep_table.h"
#include "tests/reports/synthetic_sweep.h"
#include "tests/scratch_dir.h"

namespace skinsim::reports {
namespace {

namespace fs = std::filesystem;

std::string temp_file(const std::string& name) {
  return (skinsim::testing::scratch_root("skinsim_reports_json") / name).string();
}

std::string error_of(const nlohmann::json& j) {
  try {
    (void)j.get<results::SweepTable>();
  } catch (const results::ResultsError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SweepJson, RoundTripIsExact) {
  results::SweepTable sweep = testing::synthetic_sweep();
  sweep.rows[2].programs = {{"skin", "skin_fs", 3.1e6, 30, 18, 7, 4, 1}};
  const std::string path = temp_file("results.json");
  write_sweep_json(sweep, path);
  const results::SweepTable back = results::read_sweep_json(path);
  // Serialising the read-back table gives the same document, field for field.
  EXPECT_EQ(nlohmann::json(back), nlohmann::json(sweep));
  ASSERT_EQ(back.rows.size(), 16u);
  EXPECT_EQ(back.rows[5].passes[3].dram_bytes_by_cause,
            sweep.rows[5].passes[3].dram_bytes_by_cause);
  EXPECT_DOUBLE_EQ(back.rows[5].frame_ms, sweep.rows[5].frame_ms);
  EXPECT_DOUBLE_EQ(back.rows[5].energy_mj_high, sweep.rows[5].energy_mj_high);
  EXPECT_DOUBLE_EQ(back.rows[5].passes[3].render_end_ms, sweep.rows[5].passes[3].render_end_ms);
  EXPECT_EQ(back.rows[5].knobs.at("lut"), "32x128");
  ASSERT_EQ(back.rows[2].programs.size(), 1u);
  EXPECT_EQ(back.rows[2].programs[0].texture_reads_dependent, 1);
  ASSERT_TRUE(back.heatmap);
  EXPECT_EQ(back.heatmap->bottleneck, sweep.heatmap->bottleneck);
  EXPECT_EQ(back.sensitivity[1].unit, "KB");
  for (const auto& entry : fs::directory_iterator(fs::path(path).parent_path())) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos)
        << "temporary file left behind: " << entry.path();
  }
}

TEST(SweepJson, WithoutHeatmapRoundTrips) {
  results::SweepTable sweep = testing::synthetic_sweep();
  sweep.heatmap.reset();
  const results::SweepTable back = nlohmann::json(sweep).get<results::SweepTable>();
  EXPECT_FALSE(back.heatmap);
}

TEST(SweepJson, ErrorsNameTheField) {
  nlohmann::json j = testing::synthetic_sweep();
  j["rows"][3]["frame_ms"] = "fast";
  EXPECT_NE(error_of(j).find("rows[3].frame_ms"), std::string::npos) << error_of(j);

  j = testing::synthetic_sweep();
  j["rows"][2].erase("id");
  EXPECT_NE(error_of(j).find("rows[2].id: missing"), std::string::npos) << error_of(j);

  j = testing::synthetic_sweep();
  j["rows"][1]["id"] = j["rows"][0]["id"];
  EXPECT_NE(error_of(j).find("rows[1].id: duplicate"), std::string::npos) << error_of(j);

  j = testing::synthetic_sweep();
  j["heatmap"]["ms"].erase(0);
  EXPECT_NE(error_of(j).find("heatmap.ms"), std::string::npos) << error_of(j);

  j = testing::synthetic_sweep();
  j["rows"][0]["passes"][1]["ms"] = -1.0;
  EXPECT_NE(error_of(j).find("rows[0].passes[1].ms"), std::string::npos) << error_of(j);

  j = testing::synthetic_sweep();
  j["rows"][0]["passes"][1]["render_end_ms"] = 0.0;
  EXPECT_NE(error_of(j).find("rows[0].passes[1]: a stage ends before it starts"), std::string::npos)
      << error_of(j);

  j = testing::synthetic_sweep();
  j["rows"][0]["passes"][1].erase("ta_start_ms");
  EXPECT_NE(error_of(j).find("rows[0].passes[1]"), std::string::npos) << error_of(j);

  j = testing::synthetic_sweep();
  j["rows"][4]["error_image"] = "../../etc/passwd";
  EXPECT_NE(error_of(j).find("rows[4].error_image"), std::string::npos) << error_of(j);

  j = testing::synthetic_sweep();
  j["rows"][3].erase("energy_mj_high");
  EXPECT_NE(error_of(j).find("rows[3].energy_mj_high: missing"), std::string::npos) << error_of(j);

  j = testing::synthetic_sweep();
  j["rows"][3]["energy_mj_low"] = 1e9;  // above its estimate
  EXPECT_NE(error_of(j).find("rows[3]: energy_mj_low <= energy_mj <= energy_mj_high"),
            std::string::npos)
      << error_of(j);

  j = testing::synthetic_sweep();
  j["rows"][0]["quality"]["flip_skin"] = nullptr;
  EXPECT_NE(error_of(j).find("rows[0].quality.flip_skin"), std::string::npos) << error_of(j);
}

TEST(SweepJson, FileErrorsNameTheFile) {
  const std::string path = temp_file("broken.json");
  std::ofstream(path) << "{ not json";
  try {
    results::read_sweep_json(path);
    FAIL() << "expected io::InputError";
  } catch (const io::InputError& e) {  // io::parse_json's, as for every JSON a user may edit
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_THROW(results::read_sweep_json(temp_file("does_not_exist.json")), io::InputError);
}

TEST(SweepJson, NonFiniteValuesAreRefusedBeforeWriting) {
  results::SweepTable sweep = testing::synthetic_sweep();
  sweep.rows[0].quality["ssim_skin"] = std::nan("");
  EXPECT_THROW(write_sweep_json(sweep, temp_file("nan.json")), results::ResultsError);
}

TEST(MergedPasses, SumsRepeatedPassesAndKeepsCostliestBottleneck) {
  results::ConfigResult r;
  r.passes = {{"blur", 1.0, "texture", {{"color_store", 10}}},
              {"shade", 5.0, "alu", {}},
              {"blur", 2.0, "dram", {{"color_store", 5}, {"texture_miss", 1}}}};
  const std::vector<results::PassCost> merged = merged_passes(r);
  ASSERT_EQ(merged.size(), 2u);
  EXPECT_EQ(merged[0].name, "blur");
  EXPECT_DOUBLE_EQ(merged[0].ms, 3.0);
  EXPECT_EQ(merged[0].bottleneck, "dram");
  EXPECT_DOUBLE_EQ(merged[0].dram_bytes_by_cause.at("color_store"), 15.0);
  EXPECT_EQ(dominant_bottleneck(r), "alu");
}

}  // namespace
}  // namespace skinsim::reports
