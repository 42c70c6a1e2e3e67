#include "driver/sweep/sweep_shard.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <nlohmann/json.hpp>
#include <numeric>
#include <set>

#include "driver/sweep/sweep_spec.h"
#include "io/atomic_file.h"
#include "io/json_input.h"
#include "io/temp_files.h"
#include "util/text.h"

namespace skinsim::driver {

namespace fs = std::filesystem;

namespace {

// A shard count beyond any cluster array a sweep of kDefaultMaxConfigs could use.
constexpr int kMaxShards = 100000;
// A host name or state fits in this; a failure's reason is a message of a line or a few.
constexpr std::size_t kMaxStatusText = 256;
constexpr std::size_t kMaxReasonText = 2000;

bool parse_int(std::string_view text, int& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return !text.empty() && ec == std::errc() && ptr == end;
}

fs::path status_path(const fs::path& dir, const SweepShard& shard) {
  return dir / "shards" / fmt::format("shard-{}-of-{}.json", shard.index, shard.count);
}

}  // namespace

SweepShard parse_shard(const std::string& text, const std::string& origin) {
  const auto slash = text.find('/');
  SweepShard shard;
  if (slash == std::string::npos ||
      !parse_int(std::string_view(text).substr(0, slash), shard.index) ||
      !parse_int(std::string_view(text).substr(slash + 1), shard.count)) {
    throw SweepError(
        fmt::format("{} {}: expected K/N, e.g. 0/4 (shard K of N, K from 0)", origin, text));
  }
  if (shard.count < 1 || shard.count > kMaxShards) {
    throw SweepError(fmt::format("{} {}: N must be in 1..{}", origin, text, kMaxShards));
  }
  if (shard.index < 0 || shard.index >= shard.count) {
    throw SweepError(
        fmt::format("{} {}: K must be in 0..{} (shards are numbered from 0, as Slurm's "
                    "SLURM_ARRAY_TASK_ID of --array=0-{})",
                    origin, text, shard.count - 1, shard.count - 1));
  }
  return shard;
}

std::string to_string(const SweepShard& shard) {
  return fmt::format("{}/{}", shard.index, shard.count);
}

std::vector<int> assign_shards(const std::vector<std::uint64_t>& expected_costs, int count) {
  std::vector<std::size_t> order(expected_costs.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return expected_costs[a] > expected_costs[b];
  });
  std::vector<std::uint64_t> load(static_cast<std::size_t>(count), 0);
  std::vector<int> shard_of(expected_costs.size(), 0);
  for (const std::size_t i : order) {
    const auto lightest = std::min_element(load.begin(), load.end());  // the first of equals
    *lightest += expected_costs[i];
    shard_of[i] = static_cast<int>(lightest - load.begin());
  }
  return shard_of;
}

void write_shard_status(const fs::path& sweep_dir, const ShardStatus& status) {
  nlohmann::json failed = nlohmann::json::array();
  for (const auto& [id, reason] : status.failed) failed.push_back({{"id", id}, {"reason", reason}});
  const nlohmann::json j = {{"shard", status.shard.index},
                            {"count", status.shard.count},
                            {"state", status.state},
                            {"host", status.host.empty() ? io::host_name() : status.host},
                            {"configurations", status.configurations},
                            {"failed", failed}};
  std::error_code ec;
  fs::create_directories(sweep_dir / "shards", ec);
  if (ec) {
    throw io::OutputError(fmt::format("cannot create {} (where shards keep their status): {}",
                                      (sweep_dir / "shards").string(), ec.message()));
  }
  io::write_file_atomically(status_path(sweep_dir, status.shard), j.dump(1) + "\n");
}

std::vector<ShardStatus> read_shard_statuses(const fs::path& sweep_dir) {
  std::vector<ShardStatus> statuses;
  std::error_code ec;
  std::set<fs::path> files;  // sorted: the same order on every file system
  for (const auto& entry : fs::directory_iterator(sweep_dir / "shards", ec)) {
    if (entry.path().extension() == ".json") files.insert(entry.path());
  }
  for (const fs::path& file : files) {
    try {
      const nlohmann::json j = io::read_json_file(file, "shard status");
      ShardStatus s;
      s.shard = {j.at("shard").get<int>(), j.at("count").get<int>()};
      // Printed in a merge's messages: no escape sequences, and not megabytes per configuration.
      s.state = sanitized(j.at("state").get<std::string>(), kMaxStatusText);
      s.host = sanitized(j.at("host").get<std::string>(), kMaxStatusText);
      s.configurations = j.at("configurations").get<std::vector<std::string>>();
      for (const nlohmann::json& f : j.at("failed")) {
        s.failed.emplace_back(f.at("id").get<std::string>(),
                              sanitized(f.at("reason").get<std::string>(), kMaxReasonText));
      }
      // A count parse_shard refuses is a damaged file: the ledger would size its assignment by
      // it (a hand-edited 200000000 took 1.5 GB).
      if (s.shard.count >= 1 && s.shard.count <= kMaxShards && s.shard.index >= 0 &&
          s.shard.index < s.shard.count) {
        statuses.push_back(std::move(s));
      }
    } catch (const std::exception&) {
      // Damaged or from another version: it only explains what is missing, so skip it.
    }
  }
  return statuses;
}

ShardLedger::ShardLedger(std::vector<ShardStatus> statuses,
                         const std::vector<std::uint64_t>& expected_costs)
    : statuses_(std::move(statuses)) {
  std::set<int> counts;
  for (const ShardStatus& s : statuses_) counts.insert(s.shard.count);
  for (const int count : counts) {
    assignments_.emplace_back(count, assign_shards(expected_costs, count));
  }
}

std::string ShardLedger::why_missing(std::size_t index, const std::string& id) const {
  std::vector<std::string> reasons;
  for (const auto& [count, shard_of] : assignments_) {
    const SweepShard shard{shard_of.at(index), count};
    const std::string name = to_string(shard);
    const auto it = std::find_if(statuses_.begin(), statuses_.end(), [&](const ShardStatus& s) {
      return s.shard.index == shard.index && s.shard.count == shard.count;
    });
    if (it == statuses_.end()) {
      reasons.push_back(fmt::format("shard {} has not run", name));
      continue;
    }
    const ShardStatus& s = *it;
    const auto failed = std::find_if(s.failed.begin(), s.failed.end(),
                                     [&](const auto& f) { return f.first == id; });
    if (failed != s.failed.end()) {
      reasons.push_back(fmt::format("shard {} on {} failed it: {}", name, s.host, failed->second));
    } else if (s.state == "running") {
      reasons.push_back(
          fmt::format("shard {} on {} did not finish: killed, or still running", name, s.host));
    } else if (s.state == "interrupted") {
      reasons.push_back(fmt::format("shard {} on {} was interrupted before it", name, s.host));
    } else {
      reasons.push_back(
          fmt::format("shard {} on {} ended ({}), but its result is gone or from another sweep",
                      name, s.host, s.state));
    }
  }
  return fmt::format("{}", fmt::join(reasons, "; "));
}

}  // namespace skinsim::driver
