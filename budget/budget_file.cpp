#include "budget/budget_file.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "budget/error.h"
#include "budget/metrics.h"
#include "io/read_file.h"

namespace skinsim::budget {

namespace {

// Above any display's refresh rate; a larger target is a typo (or 1e308).
constexpr double kMaxTargetFps = 1000.0;

int line_of(const toml::node& node) {
  return static_cast<int>(node.source().begin.line);
}

class Reader {
 public:
  explicit Reader(std::filesystem::path path) : path_(std::move(path)) {}

  BudgetError error(int line, const std::string& what) const {
    return BudgetError(fmt::format("{}:{}: {}", path_.string(), line, what));
  }
  BudgetError error(const toml::node& node, const std::string& what) const {
    return error(line_of(node), what);
  }

  // Rejects keys of `table` outside `allowed`, so a typo never silently does nothing.
  void check_keys(const toml::table& table, const std::vector<std::string>& allowed,
                  const std::string& where) const {
    for (const auto& [key, node] : table) {
      if (std::find(allowed.begin(), allowed.end(), key.str()) == allowed.end()) {
        throw error(node, fmt::format("unknown key '{}' in {} (allowed: {})", key.str(), where,
                                      fmt::join(allowed, ", ")));
      }
    }
  }

  std::string string_at(const toml::node& node, const std::string& field) const {
    if (const auto* s = node.as_string()) return s->get();
    throw error(node, fmt::format("{} must be a string", field));
  }

  double number_at(const toml::node& node, const std::string& field) const {
    if (const auto* f = node.as_floating_point()) {
      if (!std::isfinite(f->get())) {
        throw error(node, fmt::format("{} must be a finite number, got {:g}", field, f->get()));
      }
      return f->get();
    }
    if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
    throw error(node, fmt::format("{} must be a number", field));
  }

  int integer_at(const toml::node& node, const std::string& field) const {
    if (const auto* i = node.as_integer()) {
      if (i->get() >= 0 && i->get() <= 1'000'000'000) return static_cast<int>(i->get());
    }
    throw error(node, fmt::format("{} must be a non-negative integer", field));
  }

  // A knob value as the text set_config_field parses: strings verbatim, numbers printed.
  std::string knob_text(const toml::node& node, const std::string& field) const {
    if (const auto* s = node.as_string()) return s->get();
    if (const auto* i = node.as_integer()) return std::to_string(i->get());
    if (const auto* f = node.as_floating_point()) return fmt::format("{}", f->get());
    throw error(node, fmt::format("{} must be a string or a number", field));
  }

  // Paths in a budget file are relative to the file's directory.
  std::string resolve(const std::string& p) const {
    const std::filesystem::path candidate(p);
    if (candidate.is_absolute()) return p;
    return (path_.parent_path() / candidate).lexically_normal().string();
  }

  void read_scene(const toml::table& t, const std::string& where,
                  driver::SceneSource& scene) const {
    check_keys(t, {"path", "head_triangles", "texture_size", "skin_materials", "units_per_mm"},
               where);
    if (const toml::node* n = t.get("path")) {
      const std::string p = string_at(*n, where + ".path");
      scene.path = (p.empty() || p == "builtin") ? p : resolve(p);
    }
    if (const toml::node* n = t.get("head_triangles")) {
      scene.head_triangles = integer_at(*n, where + ".head_triangles");
      if (scene.head_triangles < 1000 || scene.head_triangles > 2'000'000) {
        throw error(*n, where + ".head_triangles must be in [1000, 2000000]");
      }
    }
    if (const toml::node* n = t.get("texture_size")) {
      scene.texture_size = integer_at(*n, where + ".texture_size");
      if (scene.texture_size < 16 || scene.texture_size > 4096) {
        throw error(*n, where + ".texture_size must be in [16, 4096]");
      }
    }
    if (const toml::node* n = t.get("skin_materials")) {
      const auto* array = n->as_array();
      if (!array) throw error(*n, where + ".skin_materials must be an array of strings");
      for (const toml::node& item : *array) {
        scene.skin_materials.push_back(string_at(item, where + ".skin_materials[]"));
      }
    }
    if (const toml::node* n = t.get("units_per_mm")) {
      const double v = number_at(*n, where + ".units_per_mm");
      if (!(v > 0.0 && v <= driver::kMaxUnitsPerMm)) {
        throw error(*n, fmt::format("{}.units_per_mm must be in (0, {:g}], got {:g}", where,
                                    driver::kMaxUnitsPerMm, v));
      }
      scene.units_per_mm = static_cast<float>(v);
    }
  }

  // `sequence`, `frames`, `fps`: checked here against the budget's knobs, so a bad sequence
  // fails when the file is read, naming its line.
  void read_sequence(const toml::table& t, const std::string& named, Budget& b) const {
    const toml::node* n = t.get("sequence");
    if (!n) {
      for (const char* key : {"frames", "fps"}) {
        if (const toml::node* k = t.get(key)) {
          throw error(*k, fmt::format("{}.{} needs {}.sequence", named, key, named));
        }
      }
      return;
    }
    std::string name = string_at(*n, named + ".sequence");
    if (name.ends_with(".toml")) name = resolve(name);
    int frames = 0;
    double fps = 0.0;
    if (const toml::node* k = t.get("frames")) {
      frames = integer_at(*k, named + ".frames");
      if (frames < 1 || frames > driver::kMaxSequenceFrames) {
        throw error(*k,
                    fmt::format("{}.frames must be in [1, {}]", named, driver::kMaxSequenceFrames));
      }
    }
    if (const toml::node* k = t.get("fps")) {
      fps = number_at(*k, named + ".fps");
      if (!(fps > 0.0 && fps <= 1000.0)) throw error(*k, named + ".fps must be in (0, 1000]");
    }
    try {
      b.sequence = driver::load_sequence(name, frames, fps);
      driver::check_sequence(*b.sequence, b.config);
    } catch (const UserError& e) {
      throw error(*n, fmt::format("{}.sequence: {}", named, e.what()));
    }
  }

  void read_pipeline(const toml::table& t, const std::string& where, Budget& budget) const {
    for (const auto& [key, node] : t) {
      const std::string field = fmt::format("{}.{}", where, key.str());
      const auto& names = pipeline::config_field_names();
      if (std::find(names.begin(), names.end(), key.str()) == names.end()) {
        throw error(node, fmt::format("unknown pipeline knob '{}' in {} (knobs: {})", key.str(),
                                      where, fmt::join(names, ", ")));
      }
      try {
        pipeline::set_config_field(budget.config, std::string(key.str()), knob_text(node, field));
      } catch (const pipeline::ConfigError& e) {
        throw error(node, fmt::format("{}: {}", field, e.what()));
      }
    }
  }

  void read_limits(const toml::table& t, const std::string& where, Budget& budget) const {
    for (const auto& [key, node] : t) {
      const std::string metric(key.str());
      const int line = line_of(node);
      const std::string at =
          fmt::format("{}:{}: budget '{}', limit '{}'", path_.string(), line, budget.name, metric);
      if (!is_known_metric_form(metric)) {
        throw BudgetError(fmt::format(
            "{}: no such metric (use frame.<kind>, <pass>.<kind> with kind one of {}, "
            "quality.<name> with name one of {}, or frame_ms.<stat> with stat one of {})",
            at, fmt::join(counter_metric_kinds(), ", "), fmt::join(quality_metric_names(), ", "),
            fmt::join(sequence_metric_stats(), ", ")));
      }
      if (is_sequence_metric(metric) && !budget.sequence) {
        throw BudgetError(at + ": a frame-time distribution needs the budget's `sequence`");
      }
      if (is_quality_metric(metric) && budget.sequence) {
        throw BudgetError(at +
                          ": a sequence budget renders no reference: limit quality in a "
                          "budget without `sequence`");
      }
      // One limit, or several on the same metric: "<= baseline * 1.05" or ["...", "..."].
      if (const auto* array = node.as_array()) {
        if (array->empty()) throw BudgetError(at + ": empty list of limits");
        for (const toml::node& item : *array) {
          budget.limits.push_back(parse_limit(
              metric, string_at(item, where + ".\"" + metric + "\""), line_of(item), at));
        }
      } else {
        budget.limits.push_back(
            parse_limit(metric, string_at(node, where + ".\"" + metric + "\""), line, at));
      }
    }
    if (budget.limits.empty()) throw error(budget.line, where + " has no limits");
    // toml++ iterates a table in key order; report limits in the order they were written.
    std::stable_sort(budget.limits.begin(), budget.limits.end(),
                     [](const Limit& a, const Limit& b) { return a.line < b.line; });
  }

  Budget read_budget(const toml::table& t, std::size_t index) const {
    Budget b;
    b.line = line_of(t);
    const std::string where = fmt::format("budget[{}]", index);
    check_keys(t,
               {"name", "device", "resolution", "target_fps", "scene", "pipeline", "sequence",
                "frames", "fps", "limits"},
               where);
    const toml::node* name = t.get("name");
    if (!name) throw error(b.line, where + " has no name");
    b.name = string_at(*name, where + ".name");
    if (b.name.empty()) throw error(*name, where + ".name is empty");
    // Names reach the terminal, JSON and JUnit XML verbatim; a control character there would
    // garble the terminal or make the XML ill-formed.
    if (std::any_of(b.name.begin(), b.name.end(),
                    [](unsigned char c) { return c < 0x20 || c == 0x7f; })) {
      throw error(*name, where + ".name contains a control character");
    }
    const std::string named = fmt::format("budget '{}'", b.name);
    const toml::node* device = t.get("device");
    if (!device) throw error(b.line, named + " has no device");
    b.device = string_at(*device, named + ".device");
    // A profile path (not a shipped name) is relative to the budget file.
    if (b.device.find('/') != std::string::npos || b.device.ends_with(".toml")) {
      b.device = resolve(b.device);
    }
    if (const toml::node* n = t.get("resolution")) {
      try {
        pipeline::set_config_field(b.config, "resolution", string_at(*n, named + ".resolution"));
      } catch (const pipeline::ConfigError& e) {
        throw error(*n, fmt::format("{}.resolution: {}", named, e.what()));
      }
    }
    if (const toml::node* n = t.get("target_fps")) {
      b.target_fps = number_at(*n, named + ".target_fps");
      if (!(b.target_fps > 0.0 && b.target_fps <= kMaxTargetFps)) {
        throw error(*n, fmt::format("{}.target_fps must be in (0, {:g}], got {:g}", named,
                                    kMaxTargetFps, b.target_fps));
      }
    }
    if (const toml::node* n = t.get("scene")) {
      const auto* table = n->as_table();
      if (!table) throw error(*n, named + ".scene must be a table");
      read_scene(*table, named + ".scene", b.scene);
    }
    if (const toml::node* n = t.get("pipeline")) {
      const auto* table = n->as_table();
      if (!table) throw error(*n, named + ".pipeline must be a table");
      // Read after the budget's own resolution, it would silently replace it.
      if (const toml::node* both = table->get("resolution"); both && t.get("resolution")) {
        throw error(*both, fmt::format("{}.pipeline.resolution: the budget's resolution is "
                                       "already given ({}.resolution): give it once",
                                       named, named));
      }
      read_pipeline(*table, named + ".pipeline", b);
    }
    // Ranges and combinations (lobe weights summing to 1) are checked on the whole config.
    try {
      b.config.validate();
    } catch (const pipeline::ConfigError& e) {
      const toml::node* knobs = t.get("pipeline");
      throw error(knobs ? line_of(*knobs) : b.line,
                  fmt::format("{}, pipeline: {}", named, e.what()));
    }
    read_sequence(t, named, b);
    const toml::node* limits = t.get("limits");
    if (!limits || !limits->as_table())
      throw error(b.line, named + " needs a [budget.limits] table");
    read_limits(*limits->as_table(), named + ".limits", b);
    return b;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace

bool Budget::needs_quality() const {
  return std::any_of(limits.begin(), limits.end(),
                     [](const Limit& l) { return is_quality_metric(l.metric); });
}

bool Budget::needs_baseline() const {
  return std::any_of(limits.begin(), limits.end(),
                     [](const Limit& l) { return l.uses_baseline(); });
}

BudgetFile parse_budget_file(const std::string& text, const std::filesystem::path& path) {
  const Reader reader(path);
  toml::table root;
  try {
    root = toml::parse(text, path.string());
  } catch (const toml::parse_error& e) {
    throw reader.error(static_cast<int>(e.source().begin.line),
                       fmt::format("malformed TOML: {}", e.description()));
  }
  BudgetFile file;
  file.path = path;
  reader.check_keys(root, {"baseline", "budget"}, "the top level");
  std::filesystem::path baseline = path;
  baseline.replace_extension(".baseline.json");
  file.baseline_path = baseline;
  if (const toml::node* n = root.get("baseline")) {
    file.baseline_path = reader.resolve(reader.string_at(*n, "baseline"));
  }
  const toml::node* budgets = root.get("budget");
  const toml::array* array = budgets ? budgets->as_array() : nullptr;
  if (!array || array->empty()) {
    throw reader.error(budgets ? line_of(*budgets) : 1,
                       "no budgets: add at least one [[budget]] table");
  }
  std::set<std::string> names;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& node = *array->get(i);
    const auto* table = node.as_table();
    if (!table) throw reader.error(node, "budget must be an array of tables ([[budget]])");
    Budget b = reader.read_budget(*table, i);
    if (!names.insert(b.name).second) {
      throw reader.error(b.line, fmt::format("duplicate budget name '{}'", b.name));
    }
    file.budgets.push_back(std::move(b));
  }
  return file;
}

BudgetFile load_budget_file(const std::filesystem::path& path) {
  return parse_budget_file(io::read_regular_file(path, "budget file"), path);
}

}  // namespace skinsim::budget
