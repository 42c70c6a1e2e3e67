// Baselines: the measured metrics of every budget, recorded by `skinsim baseline --update`
// and stored beside the budget file (JSON). Each entry records what it was measured with,
// so `skinsim check` can warn when the tool, the device profile or the budget's definition
// has changed since.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "budget/metrics.h"

namespace skinsim::budget {

struct BaselineEntry {
  std::string device;       // profile name
  std::string device_hash;  // hash of the profile file's bytes (device_fingerprint.h)
  // What the budget measured (definition_fingerprint.h); empty in baselines that predate it.
  std::string definition_hash;
  MetricValues metrics;
};

struct Baseline {
  std::string skinsim_version;
  std::map<std::string, BaselineEntry> budgets;  // by budget name
};

// Throws BudgetError naming the file (and the JSON field) when it is unreadable or malformed.
Baseline load_baseline(const std::filesystem::path& path);
// Written atomically, keys sorted, numbers round-trip exactly.
void save_baseline(const Baseline& baseline, const std::filesystem::path& path);

// When the baseline was recorded with another skinsim version, or the budget's entry with
// another device profile (name or file contents), a one-line warning; else nothing.
std::optional<std::string> version_warning(const Baseline& baseline, const std::string& version);
// When the budget's definition (device, scene, knobs) differs from the one its entry was
// recorded with, or the entry predates definition fingerprints, a one-line warning.
std::optional<std::string> definition_warning(const Baseline& baseline, const std::string& budget,
                                              const std::string& definition_hash,
                                              const std::string& budget_file);
std::optional<std::string> device_warning(const Baseline& baseline, const std::string& budget,
                                          const std::string& device,
                                          const std::string& device_hash);

}  // namespace skinsim::budget
