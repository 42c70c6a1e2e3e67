// For every shipped SGX device: no simulated throughput exceeds its spec peak, each benchmark is
// bound by the unit it was built to stress, and texture/ALU/bandwidth-bound passes come
// close to their peak (the passes are large enough for per-tile and per-render overheads
// to be small).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "microbench/spec_peaks.h"
#include "tests/microbench/test_support.h"

namespace skinsim::microbench {
namespace {

using gpu_model::Unit;
using testing::find;
using testing::kPeakSlack;

class Limits : public ::testing::TestWithParam<std::string> {
 protected:
  // All benchmarks once per device, shared by the tests of that device.
  static const std::vector<MicrobenchResult>& results(const std::string& device) {
    static std::map<std::string, std::vector<MicrobenchResult>> cache;
    auto it = cache.find(device);
    if (it == cache.end()) {
      it = cache
               .emplace(device,
                        run_microbenchmarks(testing::profile(device), testing::test_options()))
               .first;
    }
    return it->second;
  }
  const std::vector<MicrobenchResult>& results() const { return results(GetParam()); }
  gpu_model::DeviceProfile profile() const { return testing::profile(GetParam()); }
};

TEST_P(Limits, EveryBenchmarkRanAndReportsItsPeak) {
  ASSERT_EQ(results().size(), microbenchmark_names().size());
  for (const MicrobenchResult& r : results()) {
    EXPECT_GT(r.value, 0.0) << r.name;
    EXPECT_GT(r.pass_ms, 0.0) << r.name;
    EXPECT_NEAR(r.ratio, r.value / r.peak, 1e-12) << r.name;
    EXPECT_FALSE(r.shows.empty()) << r.name;
  }
}

TEST_P(Limits, FillRateNeverExceedsTmuPeak) {
  const SpecPeak peak = texel_fill_peak(profile());
  for (const char* name : {"fill_blended", "fill_opaque"}) {
    const MicrobenchResult& r = find(results(), name);
    EXPECT_DOUBLE_EQ(r.peak, peak.value) << name;
    EXPECT_LE(r.value, r.peak * kPeakSlack) << name;
    // Texture-bound: only tile and render overheads separate it from the peak.
    if (r.bottleneck == Unit::kTexture) {
      EXPECT_GT(r.ratio, 0.85) << name;
    }
  }
}

// With HSR only the front layer is shaded, so the pass is bound by its texture reads or, when
// the TMUs outrun the bus, by resolving the target: never by the overdraw (ISP or USSE).
TEST_P(Limits, OpaqueFillIsBoundByTexturesOrResolveNotOverdraw) {
  const MicrobenchResult& r = find(results(), "fill_opaque");
  EXPECT_TRUE(r.bottleneck == Unit::kTexture || r.bottleneck == Unit::kBandwidth)
      << gpu_model::unit_name(r.bottleneck);
}

// Blended layers cost a texture read on the TMUs and, on SGX, the blend in the USSE. Which
// one binds follows from the profile: per fragment per core, (texture issue + blend cycles)
// / pipes against 1 / (TMUs x bilinear rate). SGX554 (8 pipes) is texture-bound; SGX543
// (4 pipes) with 2-cycle blending is ALU-bound.
TEST_P(Limits, BlendedFillIsBoundByTmuOrUsseBlendingAsTheProfilePredicts) {
  const gpu_model::DeviceProfile p = profile();
  const double usse =
      (p.texture_issue_cycles.value + p.blend_cycles.value) / p.pipes_per_core.value;
  const double tmu = 1.0 / (p.tmus_per_core.value * p.bilinear_per_tmu_clock.value);
  const MicrobenchResult& r = find(results(), "fill_blended");
  EXPECT_EQ(r.bottleneck, usse > tmu ? Unit::kAlu : Unit::kTexture);
  // Either way the rate is within the slower unit's bound.
  EXPECT_GT(r.ratio, 0.85 * std::min(1.0, tmu / usse));
  EXPECT_EQ(r.counters.fragments_blended, r.counters.fragments_shaded);
}

TEST_P(Limits, AluRateNeverExceedsPeakAndIsAluBound) {
  const MicrobenchResult& r = find(results(), "alu_mad_chain");
  EXPECT_DOUBLE_EQ(r.peak, alu_peak_gflops(profile()).value);
  EXPECT_LE(r.value, r.peak * kPeakSlack);
  EXPECT_EQ(r.bottleneck, Unit::kAlu);
  // One vec4 MAD per pipe every vector_op_cycles clocks.
  EXPECT_GT(r.ratio, 0.9 / profile().vector_op_cycles.value);
}

TEST_P(Limits, AluChainProfileIsExactlyTheMads) {
  const MicrobenchResult& r = find(results(), "alu_mad_chain");
  ASSERT_EQ(r.counters.draws.size(), 1u);
  const sim::OpProfile& ops = r.counters.draws[0].fragment_profile;
  EXPECT_EQ(ops.vector_ops, static_cast<std::uint32_t>(testing::test_options().alu_vector_ops));
  EXPECT_EQ(ops.scalar_ops + ops.transcendental_ops + ops.texture_reads(), 0u);
}

TEST_P(Limits, BandwidthNeverExceedsAchievableAndIsBandwidthBound) {
  const SpecPeak achievable = achievable_bandwidth(profile());
  for (const char* name : {"bandwidth_copy", "bandwidth_resolve"}) {
    const MicrobenchResult& r = find(results(), name);
    EXPECT_DOUBLE_EQ(r.peak, achievable.value) << name;
    EXPECT_LE(r.value, r.peak * kPeakSlack) << name;
    EXPECT_EQ(r.bottleneck, Unit::kBandwidth) << name;
    EXPECT_GT(r.ratio, 0.9) << name;
  }
}

TEST_P(Limits, CopyReadsEveryTexelLineOnce) {
  // RGBA32F is 16 bytes a texel, read 1:1: the texture cache cannot hold a tile's footprint
  // for reuse across tiles, and every line is needed, so DRAM reads equal the texture size.
  const MicrobenchResult& r = find(results(), "bandwidth_copy");
  const double pixels = static_cast<double>(r.counters.width) * r.counters.height;
  EXPECT_DOUBLE_EQ(r.timing.dram.texture, 16.0 * pixels);
  EXPECT_DOUBLE_EQ(r.timing.dram.color_store, 16.0 * pixels);
}

TEST_P(Limits, TriangleRateNeverExceedsTilerPeak) {
  const SpecPeak peak = tiler_peak(profile());
  for (const char* name : {"triangles_visible", "triangles_offscreen", "triangles_backface"}) {
    const MicrobenchResult& r = find(results(), name);
    EXPECT_DOUBLE_EQ(r.peak, peak.value) << name;
    EXPECT_LE(r.value, r.peak * kPeakSlack) << name;
  }
}

TEST_P(Limits, CulledTrianglesAreTilerBound) {
  const MicrobenchResult& off = find(results(), "triangles_offscreen");
  EXPECT_EQ(off.bottleneck, Unit::kTiler);
  EXPECT_EQ(off.counters.triangles_culled_frustum, off.counters.triangles_in);
  EXPECT_EQ(off.counters.triangles_binned, 0u);
  EXPECT_GT(off.ratio, 0.95);

  const MicrobenchResult& back = find(results(), "triangles_backface");
  EXPECT_EQ(back.bottleneck, Unit::kTiler);
  EXPECT_EQ(back.counters.triangles_culled_backface, back.counters.triangles_in);
  EXPECT_EQ(back.counters.fragments_shaded, 0u);
  EXPECT_GT(back.ratio, 0.95);
}

// Visible triangles also go through the parameter buffer: on a narrow memory bus that round
// trip, not setup, can be the limit.
TEST_P(Limits, VisibleTrianglesAreTilerOrParameterBufferBound) {
  const MicrobenchResult& r = find(results(), "triangles_visible");
  EXPECT_TRUE(r.bottleneck == Unit::kTiler || r.bottleneck == Unit::kBandwidth)
      << gpu_model::unit_name(r.bottleneck);
  EXPECT_EQ(r.counters.triangles_binned, r.counters.triangles_in);
  EXPECT_EQ(r.counters.fragments_shaded,
            static_cast<std::uint64_t>(r.counters.width) * r.counters.height);
}

INSTANTIATE_TEST_SUITE_P(ShippedDevices, Limits, ::testing::ValuesIn(testing::kShippedDevices),
                         [](const ::testing::TestParamInfo<std::string>& device) {
                           return device.param;
                         });

}  // namespace

// Today's devices: the profile's figures reproduce the datasheet per-clock rates (FP32 FLOP
// and bilinear texels per core per clock), and the emulated ALU and copy passes reach them.
struct PublishedPerClock {
  const char* device;
  double flop_per_core_clock;    // FP32, an FMA is 2 FLOP
  double texels_per_core_clock;  // bilinear
};

class TodaysDevices : public ::testing::TestWithParam<PublishedPerClock> {};

TEST_P(TodaysDevices, MicrobenchPeaksAreTheDatasheetPerClockRates) {
  const PublishedPerClock& published = GetParam();
  const gpu_model::DeviceProfile p = testing::profile(published.device);
  const double core_mhz = p.cores.value * p.clock_mhz.value;
  EXPECT_DOUBLE_EQ(alu_peak_gflops(p).value * 1e3 / core_mhz, published.flop_per_core_clock);
  EXPECT_DOUBLE_EQ(texel_fill_peak(p).value / core_mhz, published.texels_per_core_clock);
  // These GPUs finish a 512x384 pass in tens of microseconds, where the fixed per-render
  // cost is a fifth of it; at 1024x768 it is under a tenth.
  MicrobenchOptions options;
  options.width = 1024;
  options.height = 768;
  options.only = {"alu_mad_chain", "bandwidth_copy"};
  const std::vector<MicrobenchResult> results = run_microbenchmarks(p, options);
  const MicrobenchResult& alu = find(results, "alu_mad_chain");
  EXPECT_EQ(alu.bottleneck, Unit::kAlu);
  EXPECT_LE(alu.value, alu.peak * kPeakSlack);
  EXPECT_GT(alu.ratio, 0.9);
  const MicrobenchResult& copy = find(results, "bandwidth_copy");
  EXPECT_EQ(copy.bottleneck, Unit::kBandwidth);
  EXPECT_GT(copy.ratio, 0.9);
}

// A15: 128 FP32 FMA lanes per core (PT); Mali-G715: 256 FP32 ops and 8 texels per core per
// clock (Arm GPU datasheet); Adreno 740 is one modelled core of 1536 lanes (1.8 TF at 600
// MHz, AZ). Texel rates of A15 and Adreno are the profiles' assumptions (not published).
INSTANTIATE_TEST_SUITE_P(PerClock, TodaysDevices,
                         ::testing::Values(PublishedPerClock{"a15", 256.0, 8.0},
                                           PublishedPerClock{"mali-g715", 256.0, 8.0},
                                           PublishedPerClock{"adreno740", 3072.0, 48.0}),
                         [](const ::testing::TestParamInfo<PublishedPerClock>& p) {
                           std::string name = p.param.device;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace skinsim::microbench
