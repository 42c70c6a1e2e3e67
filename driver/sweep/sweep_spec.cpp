#include "driver/sweep/sweep_spec.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>

#include "pipeline/knob.h"

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

// KnobSpec::id_prefix; a device is named by its profile, being no knob of the config.
std::string id_prefix(const std::string& knob) {
  if (knob == "device") return "";
  const pipeline::KnobSpec& k = pipeline::find_knob(knob);
  return k.id_prefix.value_or(k.name);
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

void require_not_swept(const SweepSpec& spec, const FixedKnob& fixed) {
  for (const SweepAxis& axis : spec.axes) {
    if (axis.knob == fixed.knob) {
      throw SweepError(fmt::format(
          "{}: {} is also swept ({}), which sets it in every configuration: drop one of the two",
          fixed.origin, fixed.knob, axis.origin));
    }
  }
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

namespace {

// The knobs pipeline::knob_applies reads to decide whether another knob applies: the
// technique, and the specular model (the LUT knobs need the KS LUT).
bool decides_applicability(const std::string& knob) {
  return knob != "device" && pipeline::find_knob(knob).decides;
}

// One value of each deciding axis, and which axes the configurations with those values use.
struct Group {
  std::vector<std::size_t> index;  // per axis: the deciding axes' value index, else 0
  std::vector<bool> used;          // per axis
};

// The sweep with its values canonicalised and the deciding axes' combinations folded: a
// configuration is a group plus one value of each used non-deciding axis.
struct FoldedSweep {
  SweepConfig base;
  std::vector<std::vector<std::string>> values;  // canonical, per axis
  std::vector<Group> groups;
};

std::string invalid_configuration(const std::vector<std::string>& label_parts,
                                  const pipeline::ConfigError& e) {
  return fmt::format("configuration '{}' is invalid: {}", label(label_parts), e.what());
}

// An axis value a group's technique does not use is never built, but is still checked with
// that technique (scale 2 is wrong for wrap too), so a typo is not hidden by the folding.
void validate_unused_values(const SweepSpec& spec,
                            const std::vector<std::vector<std::string>>& values,
                            const SweepConfig& group_config, const Group& g) {
  std::vector<std::string> deciding_label;
  for (std::size_t a = 0; a < values.size(); ++a) {
    if (g.used[a] && decides_applicability(spec.axes[a].knob)) {
      deciding_label.push_back(spec.axes[a].knob + " " + values[a][g.index[a]]);
    }
  }
  for (std::size_t a = 0; a < values.size(); ++a) {
    if (g.used[a]) continue;
    for (const std::string& value : values[a]) {
      SweepConfig c = group_config;
      set_knob(c, spec.axes[a].knob, value);
      try {
        c.config.validate();
      } catch (const pipeline::ConfigError& e) {
        std::vector<std::string> parts = deciding_label;
        parts.push_back(spec.axes[a].knob + " " + value);
        throw SweepError(invalid_configuration(parts, e));
      }
    }
  }
}

FoldedSweep fold_sweep(const SweepSpec& spec) {
  FoldedSweep f;
  f.base.device = "ipad4";
  for (const FixedKnob& fixed : spec.fixed) {
    require_knob(fixed.knob, fixed.origin);
    set_knob(f.base, fixed.knob, canonical_value(fixed.knob, fixed.value, fixed.origin));
  }
  // Canonical values per axis; a value given twice would make two identical configurations.
  std::vector<std::vector<std::string>> deciding;  // the deciding axes' values, others one
  for (const SweepAxis& axis : spec.axes) {
    require_knob(axis.knob, axis.origin);
    if (axis.values.empty()) throw SweepError(axis.origin + ": no values given");
    std::vector<std::string>& canon = f.values.emplace_back();
    for (const std::string& v : axis.values) {
      std::string c = canonical_value(axis.knob, v, axis.origin);
      if (std::find(canon.begin(), canon.end(), c) != canon.end()) {
        throw SweepError(fmt::format("{}: value '{}' given twice", axis.origin, v));
      }
      canon.push_back(std::move(c));
    }
    deciding.push_back(decides_applicability(axis.knob) ? canon
                                                        : std::vector<std::string>{canon[0]});
  }
  // Only the deciding axes are enumerated here (at most techniques x specular models).
  std::set<std::vector<std::size_t>> seen;
  std::vector<std::size_t> index(deciding.size(), 0);
  do {
    SweepConfig c = f.base;
    for (std::size_t a = 0; a < deciding.size(); ++a) {
      if (decides_applicability(spec.axes[a].knob))
        set_knob(c, spec.axes[a].knob, deciding[a][index[a]]);
    }
    Group g{index, std::vector<bool>(index.size())};
    // A deciding axis the technique does not use keeps its base value (then folds with the
    // group of its first value); the other axes' use follows from that configuration.
    for (std::size_t a = 0; a < deciding.size(); ++a) {
      const std::string& knob = spec.axes[a].knob;
      if (!decides_applicability(knob) || pipeline::knob_applies(c.config, knob)) continue;
      set_knob(c, knob, base_value(f.base, knob));
      g.index[a] = 0;
    }
    for (std::size_t a = 0; a < deciding.size(); ++a) {
      const std::string& knob = spec.axes[a].knob;
      g.used[a] = knob == "device" || pipeline::knob_applies(c.config, knob);
    }
    validate_unused_values(spec, f.values, c, g);
    std::vector<std::size_t> key = g.index;
    for (std::size_t a = 0; a < key.size(); ++a) {
      if (!g.used[a]) key[a] = SIZE_MAX;  // unused: the base value, whatever the index
    }
    if (seen.insert(key).second) f.groups.push_back(std::move(g));
  } while (advance(index, deciding));
  return f;
}

// The product of the used non-deciding axes' sizes in one group, saturating at SIZE_MAX.
std::size_t group_size(const FoldedSweep& f, const Group& g, const SweepSpec& spec) {
  std::size_t n = 1;
  for (std::size_t a = 0; a < f.values.size(); ++a) {
    if (!g.used[a] || decides_applicability(spec.axes[a].knob)) continue;
    if (__builtin_mul_overflow(n, f.values[a].size(), &n)) return SIZE_MAX;
  }
  return n;
}

std::size_t count_folded(const FoldedSweep& f, const SweepSpec& spec) {
  std::size_t total = 0;
  for (const Group& g : f.groups) {
    if (__builtin_add_overflow(total, group_size(f, g, spec), &total)) return SIZE_MAX;
  }
  return total;
}

SweepConfig make_config(const FoldedSweep& f, const SweepSpec& spec, const Group& g,
                        const std::vector<std::size_t>& index) {
  SweepConfig c = f.base;
  std::vector<std::string> id_parts, label_parts;
  for (std::size_t a = 0; a < f.values.size(); ++a) {
    const std::string& knob = spec.axes[a].knob;
    const std::string value = g.used[a] ? f.values[a][index[a]] : base_value(f.base, knob);
    set_knob(c, knob, value);
    id_parts.push_back(id_part(knob, value));
    if (g.used[a]) {
      c.swept.emplace_back(knob, value);
      label_parts.push_back(knob + " " + value);
    }
  }
  try {
    c.config.validate();
  } catch (const pipeline::ConfigError& e) {
    throw SweepError(invalid_configuration(label_parts, e));
  }
  c.id = id_parts.empty() ? "default" : fmt::format("{}", fmt::join(id_parts, "_"));
  c.label = label(label_parts);
  return c;
}

}  // namespace

std::size_t count_sweep_configs(const SweepSpec& spec) {
  return count_folded(fold_sweep(spec), spec);
}

std::vector<SweepConfig> expand_sweep(const SweepSpec& spec, std::size_t max_configs) {
  const FoldedSweep f = fold_sweep(spec);
  const std::size_t count = count_folded(f, spec);
  if (count > max_configs) {
    throw SweepError(
        fmt::format("the sweep has {} configurations, over the limit of {} (each takes seconds and "
                    "megabytes): narrow its axes, or pass --max-configs {} to run it anyway",
                    count == SIZE_MAX ? std::string("more than 2^64") : std::to_string(count),
                    max_configs, count));
  }
  // Every configuration as its value indices (an unused axis at 0: where the unfolded
  // product first reaches it), in the unfolded product's order: the first axis slowest.
  std::vector<std::pair<std::vector<std::size_t>, const Group*>> order;
  order.reserve(count);
  for (const Group& g : f.groups) {
    std::vector<std::vector<std::string>> ranges(f.values.size(), std::vector<std::string>{""});
    for (std::size_t a = 0; a < f.values.size(); ++a) {
      if (g.used[a] && !decides_applicability(spec.axes[a].knob)) ranges[a] = f.values[a];
    }
    std::vector<std::size_t> index(f.values.size(), 0);
    do {
      std::vector<std::size_t> full = index;
      for (std::size_t a = 0; a < full.size(); ++a) {
        if (decides_applicability(spec.axes[a].knob)) full[a] = g.index[a];
      }
      order.emplace_back(std::move(full), &g);
    } while (advance(index, ranges));
  }
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });

  std::vector<SweepConfig> configs;
  std::set<std::string> ids;
  for (const auto& [index, group] : order) {
    SweepConfig c = make_config(f, spec, *group, index);
    // Different values can sanitise to one id (two profile paths with one stem): number them.
    const std::string stem = c.id;
    for (int n = 2; ids.count(c.id) != 0; ++n) c.id = fmt::format("{}-{}", stem, n);
    ids.insert(c.id);
    configs.push_back(std::move(c));
  }
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

nlohmann::json config_fingerprint(const SweepConfig& config, const nlohmann::json& scene, int width,
                                  int height) {
  nlohmann::json knobs = nlohmann::json::object();
  for (const auto& [name, value] : all_knobs(config, width, height)) knobs[name] = value;
  return {{"knobs", knobs}, {"scene", scene}};
}

}  // namespace skinsim::driver
