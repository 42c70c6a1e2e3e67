// How the benchmarks respond to what they vary: layers, clock, host threads.
#include <gtest/gtest.h>

#include "tests/microbench/test_support.h"

namespace skinsim::microbench {
namespace {

using testing::find;

std::vector<MicrobenchResult> run_only(const gpu_model::DeviceProfile& p,
                                       std::vector<std::string> names,
                                       MicrobenchOptions o = testing::test_options()) {
  o.only = std::move(names);
  return run_microbenchmarks(p, o);
}

// Deferred hidden-surface removal: opaque layers cost depth tests, not shading.
TEST(Behaviour, OpaqueFillShadesEachPixelOnceForAnyLayerCount) {
  const gpu_model::DeviceProfile p = testing::profile("ipad4");
  for (int layers : {1, 3, 6}) {
    MicrobenchOptions o = testing::test_options();
    o.fill_layers = layers;
    const auto results = run_only(p, {"fill_opaque", "fill_blended"}, o);
    const std::uint64_t pixels = static_cast<std::uint64_t>(o.width) * o.height;
    const MicrobenchResult& opaque = find(results, "fill_opaque");
    EXPECT_EQ(opaque.counters.fragments_shaded, pixels) << layers;
    EXPECT_EQ(opaque.counters.fragments_depth_tested, layers * pixels) << layers;
    EXPECT_EQ(opaque.counters.texture.samples(), pixels) << layers;
    const MicrobenchResult& blended = find(results, "fill_blended");
    EXPECT_EQ(blended.counters.fragments_shaded, layers * pixels) << layers;
    EXPECT_EQ(blended.counters.texture.samples(), layers * pixels) << layers;
  }
}

TEST(Behaviour, OpaqueOverdrawCostsAlmostNothing) {
  const gpu_model::DeviceProfile p = testing::profile("ipad3");
  MicrobenchOptions o = testing::test_options();
  o.fill_layers = 1;
  const double one = find(run_only(p, {"fill_opaque"}, o), "fill_opaque").pass_ms;
  o.fill_layers = 6;
  const double six = find(run_only(p, {"fill_opaque"}, o), "fill_opaque").pass_ms;
  const double six_blended = find(run_only(p, {"fill_blended"}, o), "fill_blended").pass_ms;
  EXPECT_LT(six, 1.05 * one);         // five hidden layers: depth tests only
  EXPECT_GT(six_blended, 4.0 * one);  // the same layers blended: all shaded
}

TEST(Behaviour, DoubledClockGivesHigherFillRate) {
  const gpu_model::DeviceProfile base = testing::profile("ipad4");
  gpu_model::DeviceProfile fast = base;
  fast.clock_mhz.value *= 2.0;
  const MicrobenchResult slow_fill = find(run_only(base, {"fill_blended"}), "fill_blended");
  const MicrobenchResult fast_fill = find(run_only(fast, {"fill_blended"}), "fill_blended");
  EXPECT_GT(fast_fill.value, 1.8 * slow_fill.value);
  EXPECT_LE(fast_fill.value, fast_fill.peak * testing::kPeakSlack);
  EXPECT_DOUBLE_EQ(fast_fill.peak, 2.0 * slow_fill.peak);
}

TEST(Behaviour, MoreAluOpsTakeProportionallyLonger) {
  const gpu_model::DeviceProfile p = testing::profile("ipad3");
  MicrobenchOptions o = testing::test_options();
  o.alu_vector_ops = 32;
  const MicrobenchResult short_chain = find(run_only(p, {"alu_mad_chain"}, o), "alu_mad_chain");
  o.alu_vector_ops = 128;
  const MicrobenchResult long_chain = find(run_only(p, {"alu_mad_chain"}, o), "alu_mad_chain");
  EXPECT_NEAR(long_chain.pass_ms / short_chain.pass_ms, 4.0, 0.2);
  EXPECT_GE(long_chain.ratio, short_chain.ratio);  // fixed overheads matter less
}

TEST(Behaviour, WiderBusRaisesAchievedBandwidth) {
  const gpu_model::DeviceProfile base = testing::profile("iphone5");
  gpu_model::DeviceProfile wide = base;
  wide.dram_peak_gb_per_s.value *= 2.0;
  const MicrobenchResult narrow = find(run_only(base, {"bandwidth_copy"}), "bandwidth_copy");
  const MicrobenchResult doubled = find(run_only(wide, {"bandwidth_copy"}), "bandwidth_copy");
  EXPECT_GT(doubled.value, 1.8 * narrow.value);
}

TEST(Behaviour, ResultsIndependentOfHostThreads) {
  const gpu_model::DeviceProfile p = testing::profile("iphone5");
  MicrobenchOptions o = testing::test_options();
  o.threads = 1;
  const auto one = run_microbenchmarks(p, o);
  o.threads = 2;
  const auto two = run_microbenchmarks(p, o);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].name, two[i].name);
    EXPECT_EQ(one[i].value, two[i].value) << one[i].name;
    EXPECT_EQ(one[i].counters.texture.cache_misses, two[i].counters.texture.cache_misses)
        << one[i].name;
    EXPECT_EQ(one[i].counters.fragments_shaded, two[i].counters.fragments_shaded) << one[i].name;
  }
}

}  // namespace
}  // namespace skinsim::microbench
