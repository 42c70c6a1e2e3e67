// Options, selection, errors and the table / JSON views.
#include <gtest/gtest.h>

#include "gpu_model/error.h"
#include "microbench/error.h"
#include "tests/microbench/test_support.h"

namespace skinsim::microbench {
namespace {

void expect_option_error(const MicrobenchOptions& o, const std::string& field) {
  try {
    run_microbenchmarks(testing::profile("ipad4"), o);
    ADD_FAILURE() << "no error for bad '" << field << "'";
  } catch (const MicrobenchError& e) {
    EXPECT_NE(std::string(e.what()).find("'" + field + "'"), std::string::npos) << e.what();
  }
}

TEST(Api, BadOptionsNameTheOption) {
  MicrobenchOptions o = testing::test_options();
  o.width = 0;
  expect_option_error(o, "width");
  o = testing::test_options();
  o.height = -5;
  expect_option_error(o, "height");
  o = testing::test_options();
  o.fill_layers = 0;
  expect_option_error(o, "fill_layers");
  o = testing::test_options();
  o.alu_vector_ops = -1;
  expect_option_error(o, "alu_vector_ops");
  o = testing::test_options();
  o.triangle_cell_pixels = 1000;  // larger than the target
  expect_option_error(o, "triangle_cell_pixels");
  o = testing::test_options();
  o.threads = -1;
  expect_option_error(o, "threads");
}

TEST(Api, UnknownBenchmarkNameIsAnError) {
  MicrobenchOptions o = testing::test_options();
  o.only = {"fill_blended", "fill_rate_typo"};
  try {
    run_microbenchmarks(testing::profile("ipad4"), o);
    ADD_FAILURE() << "no error";
  } catch (const MicrobenchError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'fill_rate_typo'"), std::string::npos) << what;
    EXPECT_NE(what.find("fill_blended"), std::string::npos) << what;  // lists known names
  }
}

TEST(Api, NonSquareTilesAreRejectedNamingTheFields) {
  gpu_model::DeviceProfile p = testing::profile("ipad4");
  p.tile_height.value = 16;
  try {
    run_microbenchmarks(p, testing::test_options());
    ADD_FAILURE() << "no error";
  } catch (const gpu_model::ProfileError& e) {  // a profile fault, not an option's
    const std::string what = e.what();
    EXPECT_NE(what.find("tile.height"), std::string::npos) << what;
    EXPECT_NE(what.find("ipad4.toml"), std::string::npos) << what;
  }
}

TEST(Api, OnlyRunsTheSelectedBenchmarksInSuiteOrder) {
  MicrobenchOptions o = testing::test_options();
  o.only = {"alu_mad_chain", "fill_opaque"};
  const auto results = run_microbenchmarks(testing::profile("iphone5"), o);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0].name, "fill_opaque");
  EXPECT_EQ(results[1].name, "alu_mad_chain");
}

TEST(Api, TableAndJsonCarryEveryResult) {
  MicrobenchOptions o = testing::test_options();
  o.only = {"fill_blended", "bandwidth_copy"};
  const auto results = run_microbenchmarks(testing::profile("ipad4"), o);
  const std::string table = format_microbench_table(results);
  for (const MicrobenchResult& r : results) {
    EXPECT_NE(table.find(r.name), std::string::npos);
    EXPECT_NE(table.find(r.shows), std::string::npos);
    EXPECT_NE(table.find(r.peak_basis), std::string::npos);
  }
  EXPECT_NE(table.find("Mtexel/s"), std::string::npos);
  EXPECT_NE(table.find("GB/s"), std::string::npos);

  const nlohmann::json j = to_json(results);
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), 2u);
  EXPECT_EQ(j[0]["name"], "fill_blended");
  EXPECT_DOUBLE_EQ(j[0]["value"].get<double>(), results[0].value);
  EXPECT_DOUBLE_EQ(j[0]["ratio"].get<double>(), results[0].ratio);
  EXPECT_EQ(j[0]["bottleneck"], gpu_model::unit_name(results[0].bottleneck));
  EXPECT_EQ(j[1]["counters"]["texture_samples"].get<std::uint64_t>(),
            results[1].counters.texture.samples());
  EXPECT_DOUBLE_EQ(j[1]["dram_bytes"]["total"].get<double>(), results[1].timing.dram.total());
}

}  // namespace
}  // namespace skinsim::microbench
