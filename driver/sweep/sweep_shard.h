// Sharded sweeps: `skinsim sweep --shard K/N` computes one of N deterministic parts of a sweep
// into a directory it shares with the other parts (on one machine or on a cluster's shared
// file system), and a later run without --shard merges them into one report. The partition is
// engine-neutral: Slurm job arrays (scripts/slurm/sweep.sh), GNU parallel or a Kubernetes
// Indexed Job only have to hand each process its K.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace skinsim::driver {

struct SweepShard {
  int index = 0;  // K, in 0..count-1
  int count = 1;  // N
};

// Parses "K/N" (e.g. "2/8"); throws SweepError naming `origin` ("--shard") otherwise.
SweepShard parse_shard(const std::string& text, const std::string& origin);
std::string to_string(const SweepShard& shard);  // "K/N"

// The shard of each configuration, from its expected host cost: longest-processing-time-first
// greedy assignment (the costliest configuration goes to the least loaded shard, ties to the
// lower index and the earlier configuration), so shards finish at about the same time even
// when a sweep mixes cheap and expensive techniques or resolutions. It depends only on the
// costs, which depend only on the sweep: every machine computes the same partition.
std::vector<int> assign_shards(const std::vector<std::uint64_t>& expected_costs, int count);

// What one shard process did, as shards/shard-K-of-N.json in the sweep directory: written when
// it starts and rewritten when it ends, so a merge can say which shard left a configuration
// missing and why.
struct ShardStatus {
  SweepShard shard;
  std::string state;  // "running" (or killed), "finished", "failed", "interrupted"
  std::string host;
  std::vector<std::string> configurations;                  // ids assigned to it
  std::vector<std::pair<std::string, std::string>> failed;  // (id, reason)
};

void write_shard_status(const std::filesystem::path& sweep_dir, const ShardStatus& status);
// Every readable shards/*.json in the directory (damaged ones are skipped).
std::vector<ShardStatus> read_shard_statuses(const std::filesystem::path& sweep_dir);

// The shard statuses of a sweep directory, to say why a configuration has no result.
class ShardLedger {
 public:
  // `expected_costs` of the whole sweep, as assign_shards takes them.
  ShardLedger(std::vector<ShardStatus> statuses, const std::vector<std::uint64_t>& expected_costs);

  // Whether any shard process has written to the directory.
  bool empty() const { return statuses_.empty(); }

  // Why configuration `index` (id `id`) has no result: "shard 1/3 on node4 failed it:
  // <reason>", "shard 1/3 on node4 did not finish: killed, or still running", "... was
  // interrupted before it", "shard 1/3 has not run"; "" when empty().
  std::string why_missing(std::size_t index, const std::string& id) const;

 private:
  std::vector<ShardStatus> statuses_;
  std::vector<std::pair<int, std::vector<int>>> assignments_;  // (N, shard of each config)
};

}  // namespace skinsim::driver
