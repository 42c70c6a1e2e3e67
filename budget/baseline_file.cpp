#include "budget/baseline_file.h"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "budget/error.h"
#include "io/atomic_file.h"
#include "io/json_input.h"
#include "io/read_file.h"
#include "quality/json_value.h"

namespace skinsim::budget {

namespace {

constexpr const char* kFormat = "skinsim-budget-baseline/1";

}  // namespace

Baseline load_baseline(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) {
    throw BudgetError(fmt::format(
        "{}: cannot read the baseline file (record one with `skinsim baseline BUDGETS.toml "
        "--update`)",
        path.string()));
  }
  const std::string text = io::read_regular_file(path, "baseline file");
  std::string field = "(root)";
  try {
    io::require_json_depth(text, "baseline file", path);
    const nlohmann::json json = nlohmann::json::parse(text);
    field = "format";
    if (json.at("format").get<std::string>() != kFormat) {
      throw BudgetError(fmt::format("{}: format must be \"{}\"", path.string(), kFormat));
    }
    Baseline b;
    field = "skinsim_version";
    b.skinsim_version = json.at("skinsim_version").get<std::string>();
    for (const auto& [name, entry] : json.at("budgets").items()) {
      field = "budgets." + name;
      BaselineEntry e;
      e.device = entry.at("device").get<std::string>();
      e.device_hash = entry.at("device_hash").get<std::string>();
      if (entry.contains("definition_hash")) {
        field = "budgets." + name + ".definition_hash";
        e.definition_hash = entry.at("definition_hash").get<std::string>();
      }
      for (const auto& [metric, value] : entry.at("metrics").items()) {
        field = "budgets." + name + ".metrics." + metric;
        e.metrics[metric] = quality::metric_from_json(value);
      }
      b.budgets[name] = std::move(e);
    }
    return b;
  } catch (const nlohmann::json::exception& e) {
    throw BudgetError(
        fmt::format("{}: malformed baseline at {}: {}", path.string(), field, e.what()));
  }
}

void save_baseline(const Baseline& baseline, const std::filesystem::path& path) {
  nlohmann::json json;
  json["format"] = kFormat;
  json["skinsim_version"] = baseline.skinsim_version;
  json["budgets"] = nlohmann::json::object();
  for (const auto& [name, entry] : baseline.budgets) {
    nlohmann::json e;
    e["device"] = entry.device;
    e["device_hash"] = entry.device_hash;
    e["definition_hash"] = entry.definition_hash;
    e["metrics"] = nlohmann::json::object();
    for (const auto& [metric, value] : entry.metrics) {
      e["metrics"][metric] = quality::metric_to_json(value);
    }
    json["budgets"][name] = e;
  }
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  io::write_file_atomically(path.string(), json.dump(2) + "\n");
}

std::optional<std::string> version_warning(const Baseline& baseline, const std::string& version) {
  if (baseline.skinsim_version == version) return std::nullopt;
  return fmt::format("the baseline was recorded with skinsim {}, this is skinsim {}",
                     baseline.skinsim_version, version);
}

std::optional<std::string> definition_warning(const Baseline& baseline, const std::string& budget,
                                              const std::string& definition_hash,
                                              const std::string& budget_file) {
  const auto it = baseline.budgets.find(budget);
  if (it == baseline.budgets.end() || it->second.definition_hash == definition_hash) {
    return std::nullopt;
  }
  return fmt::format(
      "budget '{}': its device, scene, resolution or knobs changed since the baseline was "
      "recorded, so it is compared with a different frame (re-record it with `skinsim baseline "
      "{} --update`)",
      budget, budget_file);
}

std::optional<std::string> device_warning(const Baseline& baseline, const std::string& budget,
                                          const std::string& device,
                                          const std::string& device_hash) {
  const auto it = baseline.budgets.find(budget);
  if (it == baseline.budgets.end()) return std::nullopt;
  if (it->second.device != device) {
    return fmt::format("budget '{}': the baseline was recorded on device '{}', now '{}'", budget,
                       it->second.device, device);
  }
  if (it->second.device_hash != device_hash) {
    return fmt::format(
        "budget '{}': device profile '{}' changed since the baseline was recorded ({} -> {})",
        budget, device, it->second.device_hash, device_hash);
  }
  return std::nullopt;
}

}  // namespace skinsim::budget
