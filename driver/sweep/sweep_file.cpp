#include "driver/sweep/sweep_file.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/read_file.h"

namespace skinsim::driver {

namespace {

// "file:line: key" for messages about one TOML node.
std::string where(const std::string& name, const toml::node& node, const std::string& key) {
  return fmt::format("{}:{}: {}", name, node.source().begin.line, key);
}

// A knob value as text: TOML strings as they are, numbers as written by fmt (shortest form).
std::string value_text(const toml::node& node, const std::string& at) {
  if (const auto* s = node.as_string()) return s->get();
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  if (const auto* f = node.as_floating_point()) return fmt::format("{}", f->get());
  throw SweepError(at + ": expected a string or a number");
}

double number(const toml::node& node, const std::string& at) {
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  if (const auto* f = node.as_floating_point()) return f->get();
  throw SweepError(at + ": expected a number");
}

// The TOML integer checked against [lo, hi] before it is narrowed, so 4294968296 is refused
// rather than wrapping round to a value in range.
int integer(const toml::node& node, const std::string& at, int lo, int hi) {
  const auto* i = node.as_integer();
  if (!i) throw SweepError(at + ": expected an integer");
  const std::int64_t value = i->get();
  if (value < lo || value > hi) {
    throw SweepError(fmt::format("{}: {} is out of range: must be in [{}, {}]", at, value, lo, hi));
  }
  return static_cast<int>(value);
}

// A table's entries in file order (toml::table iterates by key): the first axis written varies
// slowest, as on the command line.
std::vector<std::pair<std::string, const toml::node*>> in_file_order(const toml::table& table) {
  std::vector<std::pair<std::string, const toml::node*>> entries;
  for (const auto& [key, node] : table) entries.emplace_back(std::string(key.str()), &node);
  std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    const toml::source_position pa = a.second->source().begin, pb = b.second->source().begin;
    return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
  });
  return entries;
}

const toml::table& table_at(const toml::node& node, const std::string& at) {
  const auto* t = node.as_table();
  if (!t) throw SweepError(at + ": expected a table");
  return *t;
}

// A device profile given as a relative .toml path is relative to the sweep file's directory
// (as in budget files), not to wherever the command runs; shipped names stay as they are.
std::string resolve_device(const std::string& value, const std::string& base_dir) {
  const std::filesystem::path path(value);
  if (path.extension() != ".toml" || path.is_absolute()) return value;
  return (std::filesystem::path(base_dir) / path).lexically_normal().string();
}

// A knob's value from the file, device paths resolved against the file's directory.
std::string knob_value(const std::string& knob, const toml::node& node, const std::string& at,
                       const std::string& base_dir) {
  const std::string text = value_text(node, at);
  return knob == "device" ? resolve_device(text, base_dir) : text;
}

void parse_axes(const toml::table& axes, const std::string& name, const std::string& base_dir,
                SweepSpec& spec) {
  for (const auto& [key, node] : in_file_order(axes)) {
    const std::string at = where(name, *node, "axes." + key);
    std::vector<std::string> values;
    if (const auto* array = node->as_array()) {
      for (const toml::node& v : *array) values.push_back(knob_value(key, v, at, base_dir));
    } else {
      values.push_back(knob_value(key, *node, at, base_dir));  // one value: a one-value axis
    }
    set_axis(spec, key, values, at);
  }
}

void parse_fixed(const toml::table& fixed, const std::string& name, const std::string& base_dir,
                 SweepSpec& spec) {
  for (const auto& [key, node] : in_file_order(fixed)) {
    const std::string at = where(name, *node, "fixed." + key);
    spec.fixed.push_back({key, knob_value(key, *node, at, base_dir), at});
  }
}

void parse_scene(const toml::table& scene, const std::string& name, const std::string& base_dir,
                 SweepSpec& spec) {
  SceneSource& s = spec.scene;
  for (const auto& [key, node] : scene) {
    const std::string k(key.str());
    const std::string at = where(name, node, "scene." + k);
    if (k == "path") {
      const auto* text = node.as_string();
      if (!text) throw SweepError(at + ": expected a string");
      s.path = text->get();
      if (!s.builtin() && std::filesystem::path(s.path).is_relative()) {
        s.path = (std::filesystem::path(base_dir) / s.path).lexically_normal().string();
      }
    } else if (k == "head_triangles") {
      s.head_triangles = integer(node, at, 1000, 2000000);
    } else if (k == "texture_size") {
      s.texture_size = integer(node, at, 16, 4096);
    } else if (k == "skin_materials") {
      const auto* array = node.as_array();
      if (!array) throw SweepError(at + ": expected an array of material names");
      s.skin_materials.clear();
      for (const toml::node& v : *array) {
        const auto* text = v.as_string();
        if (!text) throw SweepError(at + ": expected an array of material names");
        s.skin_materials.push_back(text->get());
      }
    } else if (k == "units_per_mm") {
      s.units_per_mm = static_cast<float>(number(node, at));
      if (!(s.units_per_mm > 0.0f)) throw SweepError(at + ": must be > 0");
    } else if (k == "skin_albedo") {
      const auto* text = node.as_string();
      if (!text) throw SweepError(at + ": expected a string (\"r,g,b\" or an image path)");
      s.skin_albedo = text->get();
      // An image path, like `path`, is relative to the sweep file.
      const std::filesystem::path beside = std::filesystem::path(base_dir) / s.skin_albedo;
      if (std::filesystem::path(s.skin_albedo).is_relative() &&
          std::filesystem::is_regular_file(beside)) {
        s.skin_albedo = beside.lexically_normal().string();
      }
    } else {
      throw SweepError(at +
                       ": unknown key (known: path, head_triangles, texture_size, "
                       "skin_materials, units_per_mm, skin_albedo)");
    }
  }
}

void parse_report(const toml::table& report, const std::string& name, SweepSpec& spec) {
  for (const auto& [key, node] : report) {
    const std::string k(key.str());
    const std::string at = where(name, node, "report." + k);
    if (k != "budget_ms") throw SweepError(at + ": unknown key (known: budget_ms)");
    spec.budget_ms = number(node, at);
    if (!std::isfinite(spec.budget_ms) || spec.budget_ms <= 0.0) {
      throw SweepError(at + ": must be a finite number of milliseconds > 0");
    }
  }
}

}  // namespace

SweepSpec parse_sweep_text(const std::string& text, const std::string& name,
                           const std::string& base_dir) {
  toml::table root;
  try {
    root = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    throw SweepError(fmt::format("{}:{}:{}: {}", name, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
  SweepSpec spec;
  spec.fixed.push_back({"device", "ipad4", name + ": default device"});
  const std::size_t first_fixed = spec.fixed.size();  // the file's own [fixed] knobs from here
  for (const auto& [key, node] : root) {
    const std::string k(key.str());
    const std::string at = where(name, node, k);
    if (k == "axes") {
      parse_axes(table_at(node, at), name, base_dir, spec);
    } else if (k == "fixed") {
      parse_fixed(table_at(node, at), name, base_dir, spec);
    } else if (k == "scene") {
      parse_scene(table_at(node, at), name, base_dir, spec);
    } else if (k == "report") {
      parse_report(table_at(node, at), name, spec);
    } else {
      throw SweepError(at + ": unknown table (known: axes, fixed, scene, report)");
    }
  }
  if (spec.axes.empty()) throw SweepError(name + ": no [axes] given: nothing to sweep");
  for (std::size_t i = first_fixed; i < spec.fixed.size(); ++i)
    require_not_swept(spec, spec.fixed[i]);
  // Validate every value now, so a bad one is reported against this file before any work; a
  // sweep over the limit is validated value by value (counting canonicalises every value) and
  // refused by the command unless it raises the limit.
  if (count_sweep_configs(spec) <= kDefaultMaxConfigs) expand_sweep(spec);
  return spec;
}

SweepSpec parse_sweep_file(const std::string& path) {
  return parse_sweep_text(io::read_regular_file(path, "sweep file"), path,
                          std::filesystem::path(path).parent_path().string());
}

}  // namespace skinsim::driver
