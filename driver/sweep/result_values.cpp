#include "driver/sweep/result_values.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

namespace skinsim::driver {

namespace {

void collect(const nlohmann::json& j, const std::string& path, NamedValues& out) {
  if (j.is_number()) {
    out[path] = j.get<double>();
    return;
  }
  const std::string prefix = path.empty() ? "" : path + ".";
  if (j.is_object()) {
    for (const auto& [key, value] : j.items()) {
      // Settings, not measurements: the knobs, and what the run's reference was made from.
      if (path.empty() && (key == "config" || key == "reference")) continue;
      collect(value, prefix + key, out);
    }
    return;
  }
  if (!j.is_array()) return;  // strings, booleans, null: not measurements
  std::map<std::string, int> seen;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const nlohmann::json& e = j[i];
    std::string key = std::to_string(i);
    if (e.is_object() && e.contains("name") && e["name"].is_string()) {
      key = e["name"].get<std::string>();
      const int n = ++seen[key];
      if (n > 1) key += "#" + std::to_string(n);
    }
    collect(e, prefix + key, out);
  }
}

std::string kind_of(const std::string& name) {
  const std::string first = name.substr(0, name.find('.'));
  if (first == "counters" || first == "technique") return "counter";
  if (first == "quality") return "quality";
  return "modelled";
}

double tolerance_of(const std::string& kind, const reports::Tolerances& t) {
  if (kind == "counter") return t.counter;
  if (kind == "quality") return t.quality;
  return t.modelled;
}

}  // namespace

NamedValues numeric_values(const nlohmann::json& j) {
  NamedValues out;
  collect(j, "", out);
  return out;
}

void compare_values(const NamedValues& a, const NamedValues& b,
                    const reports::Tolerances& tolerances, reports::ConfigDiff& diff) {
  std::set<std::string> names;
  for (const auto& [name, value] : a) names.insert(name);
  for (const auto& [name, value] : b) names.insert(name);
  std::vector<reports::ValueDelta> moved;
  for (const std::string& name : names) {
    reports::ValueDelta d;
    d.name = name;
    d.kind = kind_of(name);
    d.tolerance = tolerance_of(d.kind, tolerances);
    if (const auto it = a.find(name); it != a.end()) d.a = it->second;
    if (const auto it = b.find(name); it != b.end()) d.b = it->second;
    if (d.moved()) moved.push_back(std::move(d));
  }
  std::stable_sort(moved.begin(), moved.end(), [](const auto& x, const auto& y) {
    return std::fabs(x.relative_change()) > std::fabs(y.relative_change());
  });
  const auto frame_ms = [](const NamedValues& v) -> std::optional<double> {
    const auto it = v.find("timing.frame_ms");
    if (it == v.end()) return std::nullopt;
    return it->second;
  };
  diff.frame_ms_a = frame_ms(a);
  diff.frame_ms_b = frame_ms(b);
  diff.values_compared = names.size();
  diff.moved = std::move(moved);
}

}  // namespace skinsim::driver
