// Sharded sweeps: parsing K/N, the cost-balanced partition, and shards run one after another
// into one directory (interrupted, resumed, merged) giving what the one-process sweep gives.
// Concurrent shard processes and Slurm are tested in tests/slurm/.
#include "driver/sweep/sweep_shard.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>

#include "driver/sweep/sweep_results.h"
#include "driver/sweep/sweep_run.h"
#include "driver/sweep/sweep_spec.h"
#include "sweep_test_support.h"

namespace skinsim::driver {
namespace {

namespace fs = std::filesystem;
using test::options;
using test::out_dir;
using test::read_file;

TEST(SweepShard, ParsesKOfN) {
  const SweepShard s = parse_shard("2/8", "--shard");
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 8);
  EXPECT_EQ(to_string(s), "2/8");
  for (const char* bad : {"", "2", "8/8", "-1/8", "2/0", "a/8", "2/8/1", " 2/8", "2/8x"}) {
    try {
      parse_shard(bad, "--shard");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const SweepError& e) {
      EXPECT_NE(std::string(e.what()).find("--shard"), std::string::npos) << e.what();
    }
  }
}

TEST(SweepShard, BalancesExpectedCostNotCount) {
  // One expensive configuration and six cheap ones over two shards: a split by count would
  // put 9 units beside 4; the costliest-first greedy gives 7 and 6.
  const std::vector<std::uint64_t> costs = {1, 1, 6, 1, 1, 1, 2};
  const std::vector<int> shard = assign_shards(costs, 2);
  std::uint64_t load[2] = {0, 0};
  for (std::size_t i = 0; i < costs.size(); ++i) load[shard[i]] += costs[i];
  EXPECT_EQ(shard[2], 0);  // the costliest goes first, to shard 0
  EXPECT_EQ(load[0], 7u);
  EXPECT_EQ(load[1], 6u);
  // Deterministic: the same costs give the same partition, and every shard index is used.
  EXPECT_EQ(assign_shards(costs, 2), shard);
  const std::vector<int> many = assign_shards(costs, 7);
  std::vector<int> sorted = many;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> each(7);
  std::iota(each.begin(), each.end(), 0);
  EXPECT_EQ(sorted, each);
}

TEST(SweepShard, MoreShardsThanConfigurationsLeavesSomeEmpty) {
  const std::vector<int> shard = assign_shards({3, 3}, 5);
  EXPECT_EQ(shard, (std::vector<int>{0, 1}));
}

TEST(SweepShard, LedgerSaysWhichShardLeftAConfigurationAndWhy) {
  const std::vector<std::uint64_t> costs = {5, 4, 3};  // shards of 3: 0, 1, 2
  std::vector<ShardStatus> statuses = {
      {{0, 3}, "failed", "node1", {"a"}, {{"a", "frame_ms is nan"}}},
      {{1, 3}, "running", "node2", {"b"}, {}},
  };
  const ShardLedger ledger(statuses, costs);
  EXPECT_FALSE(ledger.empty());
  EXPECT_EQ(ledger.why_missing(0, "a"), "shard 0/3 on node1 failed it: frame_ms is nan");
  EXPECT_EQ(ledger.why_missing(1, "b"),
            "shard 1/3 on node2 did not finish: killed, or still running");
  EXPECT_EQ(ledger.why_missing(2, "c"), "shard 2/3 has not run");
  EXPECT_TRUE(ShardLedger({}, costs).empty());
  EXPECT_EQ(ShardLedger({}, costs).why_missing(0, "a"), "");
}

// --- shards of a real (tiny) sweep -------------------------------------------------------

SweepSpec sharded_spec() {
  SweepSpec spec;
  set_axis(spec, "technique", {"mobile", "wrap", "burley"}, "test");
  set_axis(spec, "scale", {"0.5", "0.25"}, "test");
  spec.fixed.push_back({"resolution", "128x96", "test"});
  spec.scene.head_triangles = 2000;
  spec.scene.texture_size = 64;
  return spec;  // 4 configurations: mobile at two scales, wrap, burley
}

std::string results_csv(const SweepSpec& spec, const std::vector<SweepConfig>& configs,
                        const SweepRunSummary& summary, const fs::path& dir) {
  write_sweep_data(assemble_sweep_table(spec, configs, summary.fingerprints, dir.string()),
                   dir.string());
  return read_file(dir / "results.csv");
}

TEST(SweepShard, ShardsInterruptedResumedAndMergedGiveTheOneProcessResults) {
  const SweepSpec spec = sharded_spec();
  const std::vector<SweepConfig> configs = expand_sweep(spec);
  ASSERT_EQ(configs.size(), 4u);
  const fs::path single = out_dir("shard_single");
  const std::string expected =
      results_csv(spec, configs, run_sweep(spec, configs, options(single, 1)), single);

  const fs::path dir = out_dir("shard_parts");
  // Shard 0 of 2 is interrupted after its first configuration ("Ctrl-C", or Slurm's SIGTERM).
  std::atomic<bool> cancel{false};
  SweepRunOptions first = options(dir, 1);
  first.shard = SweepShard{0, 2};
  first.cancel = &cancel;
  first.on_finished = [&](const std::string&) { cancel = true; };
  const SweepRunSummary interrupted = run_sweep(spec, configs, first);
  EXPECT_TRUE(interrupted.cancelled);
  EXPECT_EQ(interrupted.total, 4);
  ASSERT_EQ(interrupted.computed.size(), 1u);
  const int part0 = interrupted.this_part;

  // The merge computes nothing and names what is missing, and the shard responsible.
  SweepRunOptions merge = options(dir, 1);
  merge.compute = false;
  SweepRunSummary merged = run_sweep(spec, configs, merge);
  EXPECT_TRUE(merged.computed.empty());
  EXPECT_EQ(merged.left_by_shards.size(), 3u);
  int interrupted_named = 0, not_run_named = 0;
  for (const MissingConfig& m : merged.left_by_shards) {
    interrupted_named += m.reason == "shard 0/2 on " + read_shard_statuses(dir).at(0).host +
                                         " was interrupted before it";
    not_run_named += m.reason == "shard 1/2 has not run";
  }
  EXPECT_EQ(interrupted_named, part0 - 1);
  EXPECT_EQ(not_run_named, 4 - part0);

  // Shard 1 runs; shard 0 is run again and resumes.
  SweepRunOptions second = options(dir, 1);
  second.shard = SweepShard{1, 2};
  const SweepRunSummary part1 = run_sweep(spec, configs, second);
  EXPECT_EQ(part1.this_part, 4 - part0);
  EXPECT_EQ(part1.computed.size(), static_cast<std::size_t>(4 - part0));
  EXPECT_EQ(part1.references_rendered, 0);  // shard 0 rendered the shared reference
  cancel = false;
  first.on_finished = nullptr;
  const SweepRunSummary rerun = run_sweep(spec, configs, first);
  EXPECT_EQ(rerun.resumed, 1);
  EXPECT_EQ(rerun.computed.size(), static_cast<std::size_t>(part0 - 1));

  merged = run_sweep(spec, configs, merge);
  EXPECT_TRUE(merged.left_by_shards.empty());
  EXPECT_EQ(merged.resumed, 4);
  EXPECT_EQ(results_csv(spec, configs, merged, dir), expected);
  for (const ShardStatus& s : read_shard_statuses(dir)) EXPECT_EQ(s.state, "finished");
}

}  // namespace
}  // namespace skinsim::driver
