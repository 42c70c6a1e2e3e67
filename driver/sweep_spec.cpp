#include "driver/sweep_spec.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>

namespace skinsim::driver {

namespace {

bool is_pipeline_knob(const std::string& knob) {
  const auto& names = pipeline::config_field_names();
  return std::find(names.begin(), names.end(), knob) != names.end();
}

void require_knob(const std::string& knob, const std::string& origin) {
  if (knob == "device" || is_pipeline_knob(knob)) return;
  throw SweepError(fmt::format("{}: unknown knob '{}' (known: {})", origin, knob,
                               fmt::join(sweep_knob_names(), ", ")));
}

// The value as get_config_field prints it, so "1.0" and "1" name the same configuration.
std::string canonical_value(const std::string& knob, const std::string& value,
                            const std::string& origin) {
  if (knob == "device") {
    if (value.empty()) throw SweepError(origin + ": empty device name");
    return value;
  }
  pipeline::PipelineConfig scratch;
  try {
    pipeline::set_config_field(scratch, knob, value);
  } catch (const pipeline::ConfigError& e) {
    throw SweepError(fmt::format("{}: bad value '{}': {}", origin, value, e.what()));
  }
  return pipeline::get_config_field(scratch, knob);
}

// Numbers need the knob's name to be readable in an id ("scale0.5"); words do not ("mobile").
std::string id_prefix(const std::string& knob) {
  static const std::map<std::string, std::string> prefixes = {
      {"technique", ""},  {"device", ""}, {"lut_format", ""},
      {"resolution", ""}, {"gamma", ""},  {"blur_iterations", "blur"}};
  const auto it = prefixes.find(knob);
  return it != prefixes.end() ? it->second : knob;
}

std::string id_part(const std::string& knob, const std::string& value) {
  // A device given as a profile path is named by its file stem.
  std::string v = knob == "device" ? std::filesystem::path(value).stem().string() : value;
  for (char& c : v) {
    const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '.' || c == '-';
    if (!safe) c = '-';
  }
  return id_prefix(knob) + v;
}

void set_knob(SweepConfig& c, const std::string& knob, const std::string& value) {
  if (knob == "device") {
    c.device = value;
  } else {
    pipeline::set_config_field(c.config, knob, value);
  }
}

// The value a configuration has for `knob` when no axis sets it.
std::string base_value(const SweepConfig& base, const std::string& knob) {
  return knob == "device" ? base.device : pipeline::get_config_field(base.config, knob);
}

std::string label(const std::vector<std::string>& parts) {
  return parts.empty() ? "default configuration" : fmt::format("{}", fmt::join(parts, ", "));
}

// Odometer step over the axes' values, the last axis fastest; false after the last one.
bool advance(std::vector<std::size_t>& index, const std::vector<std::vector<std::string>>& values) {
  for (std::size_t a = values.size(); a > 0; --a) {
    if (++index[a - 1] < values[a - 1].size()) return true;
    index[a - 1] = 0;
  }
  return false;
}

}  // namespace

std::vector<std::string> sweep_knob_names() {
  std::vector<std::string> names = pipeline::config_field_names();
  names.push_back("device");
  return names;
}

SweepSpec default_sweep_spec() {
  SweepSpec spec;
  set_axis(spec, "scale", {"1", "0.5", "0.25", "0.125"}, "default sweep");
  set_axis(spec, "lut", {"8x32", "16x64", "32x128", "64x256"}, "default sweep");
  spec.fixed.push_back({"device", "ipad4", "default sweep"});
  return spec;
}

void set_axis(SweepSpec& spec, const std::string& knob, const std::vector<std::string>& values,
              const std::string& origin) {
  require_knob(knob, origin);
  if (values.empty()) throw SweepError(origin + ": no values given");
  SweepAxis axis{knob, values, origin};
  const auto same = [&](const SweepAxis& a) { return a.knob == knob; };
  if (const auto it = std::find_if(spec.axes.begin(), spec.axes.end(), same);
      it != spec.axes.end()) {
    *it = std::move(axis);
  } else {
    spec.axes.push_back(std::move(axis));
  }
}

std::vector<SweepConfig> expand_sweep(const SweepSpec& spec) {
  SweepConfig base;
  base.device = "ipad4";
  for (const FixedKnob& f : spec.fixed) {
    require_knob(f.knob, f.origin);
    set_knob(base, f.knob, canonical_value(f.knob, f.value, f.origin));
  }

  // Canonical values per axis; a value given twice would make two identical configurations.
  std::vector<std::vector<std::string>> values;
  for (const SweepAxis& axis : spec.axes) {
    require_knob(axis.knob, axis.origin);
    if (axis.values.empty()) throw SweepError(axis.origin + ": no values given");
    std::vector<std::string>& canon = values.emplace_back();
    for (const std::string& v : axis.values) {
      std::string c = canonical_value(axis.knob, v, axis.origin);
      if (std::find(canon.begin(), canon.end(), c) != canon.end()) {
        throw SweepError(fmt::format("{}: value '{}' given twice", axis.origin, v));
      }
      canon.push_back(std::move(c));
    }
  }

  std::vector<SweepConfig> configs;
  std::set<std::string> ids;
  std::set<std::vector<std::string>> combinations;
  std::vector<std::size_t> index(values.size(), 0);
  do {
    SweepConfig c = base;
    std::vector<std::string> full_label;
    for (std::size_t a = 0; a < values.size(); ++a) {
      const std::string& knob = spec.axes[a].knob;
      set_knob(c, knob, values[a][index[a]]);
      full_label.push_back(knob + " " + values[a][index[a]]);
    }
    try {  // every value is checked, used by this configuration's technique or not
      c.config.validate();
    } catch (const pipeline::ConfigError& e) {
      throw SweepError(
          fmt::format("configuration '{}' is invalid: {}", label(full_label), e.what()));
    }
    // An axis this configuration's technique does not use keeps the base value: the
    // combinations that differ only there render the same frame, so only the first runs.
    // The id still names every axis (the same id and fingerprint as before axes were
    // technique-aware, so earlier sweep directories resume); the label names what applies.
    std::vector<std::string> combination, id_parts, label_parts;
    for (std::size_t a = 0; a < values.size(); ++a) {
      const std::string& knob = spec.axes[a].knob;
      const bool used = knob == "device" || pipeline::knob_applies(c.config, knob);
      const std::string value = used ? values[a][index[a]] : base_value(base, knob);
      set_knob(c, knob, value);
      combination.push_back(value);
      id_parts.push_back(id_part(knob, value));
      if (used) {
        c.swept.emplace_back(knob, value);
        label_parts.push_back(knob + " " + value);
      }
    }
    if (!combinations.insert(combination).second) continue;
    const std::string stem =
        id_parts.empty() ? "default" : fmt::format("{}", fmt::join(id_parts, "_"));
    c.id = stem;
    // Different values can sanitise to one id (two profile paths with one stem): number them.
    for (int n = 2; ids.count(c.id) != 0; ++n) c.id = fmt::format("{}-{}", stem, n);
    ids.insert(c.id);
    c.label = label(label_parts);
    configs.push_back(std::move(c));
  } while (advance(index, values));
  return configs;
}

std::vector<std::pair<std::string, std::string>> all_knobs(const SweepConfig& config, int width,
                                                           int height) {
  pipeline::PipelineConfig resolved = config.config;
  resolved.width = width;
  resolved.height = height;
  std::vector<std::pair<std::string, std::string>> knobs;
  for (const std::string& name : pipeline::config_field_names()) {
    knobs.emplace_back(name, pipeline::get_config_field(resolved, name));
  }
  knobs.emplace_back("device", config.device);
  return knobs;
}

void keep_used_knobs(const SweepConfig& config, std::map<std::string, std::string>& knobs) {
  std::erase_if(knobs, [&](const auto& knob) {
    return knob.first != "device" && !pipeline::knob_applies(config.config, knob.first);
  });
}

nlohmann::json config_fingerprint(const SweepConfig& config, const SceneSource& scene, int width,
                                  int height) {
  nlohmann::json knobs = nlohmann::json::object();
  for (const auto& [name, value] : all_knobs(config, width, height)) knobs[name] = value;
  return {{"knobs", knobs},
          {"scene",
           {{"label", scene.label()},
            {"head_triangles", scene.head_triangles},
            {"texture_size", scene.texture_size},
            {"skin_materials", scene.skin_materials},
            {"units_per_mm", scene.units_per_mm}}}};
}

std::string short_hash(const std::string& text) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a offset basis
  for (const unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;  // FNV prime
  }
  return fmt::format("{:016x}", h);
}

}  // namespace skinsim::driver
