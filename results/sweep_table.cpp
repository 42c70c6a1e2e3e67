#include "results/sweep_table.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "io/json_input.h"
#include "io/read_file.h"
#include "results/error.h"

namespace skinsim::results {

using nlohmann::json;

namespace {

std::string field_path(const std::string& where, const std::string& key) {
  return where.empty() ? key : where + "." + key;
}

const json& require(const json& j, const std::string& where, const std::string& key) {
  if (!j.is_object()) throw ResultsError(where + ": expected an object");
  auto it = j.find(key);
  if (it == j.end()) throw ResultsError(field_path(where, key) + ": missing");
  return *it;
}

double number_at(const json& j, const std::string& where) {
  if (!j.is_number()) throw ResultsError(where + ": expected a number, got " + j.dump());
  return j.get<double>();
}

std::string string_at(const json& j, const std::string& where) {
  if (!j.is_string()) throw ResultsError(where + ": expected a string, got " + j.dump());
  return j.get<std::string>();
}

double req_number(const json& j, const std::string& where, const std::string& key) {
  return number_at(require(j, where, key), field_path(where, key));
}

std::string req_string(const json& j, const std::string& where, const std::string& key) {
  return string_at(require(j, where, key), field_path(where, key));
}

std::string opt_string(const json& j, const std::string& where, const std::string& key) {
  auto it = j.find(key);
  return it == j.end() ? std::string() : string_at(*it, field_path(where, key));
}

int req_int(const json& j, const std::string& where, const std::string& key) {
  const json& v = require(j, where, key);
  if (!v.is_number_integer()) {
    throw ResultsError(field_path(where, key) + ": expected an integer, got " + v.dump());
  }
  return v.get<int>();
}

const json& array_at(const json& j, const std::string& where) {
  if (!j.is_array()) throw ResultsError(where + ": expected an array");
  return j;
}

std::string index_path(const std::string& where, std::size_t i) {
  return where + "[" + std::to_string(i) + "]";
}

template <typename T>
std::map<std::string, T> map_at(const json& j, const std::string& where) {
  if (!j.is_object()) throw ResultsError(where + ": expected an object");
  std::map<std::string, T> out;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string path = where + "." + it.key();
    if constexpr (std::is_same_v<T, double>) {
      out[it.key()] = number_at(it.value(), path);
    } else {
      out[it.key()] = string_at(it.value(), path);
    }
  }
  return out;
}

std::vector<std::string> strings_at(const json& j, const std::string& where) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < array_at(j, where).size(); ++i) {
    out.push_back(string_at(j[i], index_path(where, i)));
  }
  return out;
}

PassCost parse_pass(const json& j, const std::string& where) {
  PassCost p;
  p.name = req_string(j, where, "name");
  p.ms = req_number(j, where, "ms");
  p.bottleneck = opt_string(j, where, "bottleneck");
  p.ta_start_ms = req_number(j, where, "ta_start_ms");
  p.ta_end_ms = req_number(j, where, "ta_end_ms");
  p.render_start_ms = req_number(j, where, "render_start_ms");
  p.render_end_ms = req_number(j, where, "render_end_ms");
  if (j.contains("dram_bytes_by_cause")) {
    p.dram_bytes_by_cause =
        map_at<double>(j["dram_bytes_by_cause"], field_path(where, "dram_bytes_by_cause"));
  }
  return p;
}

ProgramCost parse_program(const json& j, const std::string& where) {
  ProgramCost p;
  p.pass = req_string(j, where, "pass");
  p.program = req_string(j, where, "program");
  p.fragments = req_number(j, where, "fragments");
  p.vector_ops = req_int(j, where, "vector_ops");
  p.scalar_ops = req_int(j, where, "scalar_ops");
  p.transcendental_ops = req_int(j, where, "transcendental_ops");
  p.texture_reads_independent = req_int(j, where, "texture_reads_independent");
  p.texture_reads_dependent = req_int(j, where, "texture_reads_dependent");
  return p;
}

bool req_bool(const json& j, const std::string& where, const std::string& key) {
  const json& v = require(j, where, key);
  if (!v.is_boolean()) {
    throw ResultsError(field_path(where, key) + ": expected true or false, got " + v.dump());
  }
  return v.get<bool>();
}

FrameComparison parse_comparison(const json& j, const std::string& where) {
  FrameComparison c;
  c.against = req_string(j, where, "against");
  c.flip_mean = req_number(j, where, "flip_mean");
  c.flip_p99 = req_number(j, where, "flip_p99");
  c.visible_px = req_number(j, where, "visible_px");
  c.visible = req_bool(j, where, "visible");
  return c;
}

std::optional<FrameComparison> opt_comparison(const json& j, const std::string& where,
                                              const std::string& key) {
  auto it = j.find(key);
  if (it == j.end() || it->is_null()) return std::nullopt;
  return parse_comparison(*it, field_path(where, key));
}

ConfigResult parse_config(const json& j, const std::string& where) {
  ConfigResult c;
  c.id = req_string(j, where, "id");
  c.label = opt_string(j, where, "label");
  if (j.contains("knobs")) c.knobs = map_at<std::string>(j["knobs"], field_path(where, "knobs"));
  c.frame_ms = req_number(j, where, "frame_ms");
  c.frame_ms_low = req_number(j, where, "frame_ms_low");
  c.frame_ms_high = req_number(j, where, "frame_ms_high");
  c.fps = req_number(j, where, "fps");
  c.dram_bytes = req_number(j, where, "dram_bytes");
  c.energy_mj = req_number(j, where, "energy_mj");
  c.energy_mj_low = req_number(j, where, "energy_mj_low");
  c.energy_mj_high = req_number(j, where, "energy_mj_high");
  if (j.contains("passes")) {
    const std::string p = field_path(where, "passes");
    const json& passes = array_at(j["passes"], p);
    for (std::size_t i = 0; i < passes.size(); ++i) {
      c.passes.push_back(parse_pass(passes[i], index_path(p, i)));
    }
  }
  if (j.contains("programs")) {
    const std::string p = field_path(where, "programs");
    const json& programs = array_at(j["programs"], p);
    for (std::size_t i = 0; i < programs.size(); ++i) {
      c.programs.push_back(parse_program(programs[i], index_path(p, i)));
    }
  }
  if (j.contains("quality")) c.quality = map_at<double>(j["quality"], field_path(where, "quality"));
  c.frame_image = opt_string(j, where, "frame_image");
  c.error_image = opt_string(j, where, "error_image");
  c.reference_image = opt_string(j, where, "reference_image");
  c.visible_vs_reference = req_bool(j, where, "visible_vs_reference");
  c.group = opt_string(j, where, "group");
  c.vs_finest = opt_comparison(j, where, "vs_finest");
  c.vs_best = opt_comparison(j, where, "vs_best");
  if (j.contains("sequence"))
    c.sequence = parse_sequence_summary(j["sequence"], where + ".sequence");
  return c;
}

TileHeatmap parse_heatmap(const json& j, const std::string& where) {
  TileHeatmap h;
  h.tiles_x = req_int(j, where, "tiles_x");
  h.tiles_y = req_int(j, where, "tiles_y");
  h.tile_size = req_int(j, where, "tile_size");
  const std::string ms_path = field_path(where, "ms");
  const json& ms = array_at(require(j, where, "ms"), ms_path);
  for (std::size_t i = 0; i < ms.size(); ++i)
    h.ms.push_back(number_at(ms[i], index_path(ms_path, i)));
  if (j.contains("bottleneck"))
    h.bottleneck = strings_at(j["bottleneck"], field_path(where, "bottleneck"));
  h.pass_name = opt_string(j, where, "pass_name");
  h.config_id = opt_string(j, where, "config_id");
  return h;
}

SensitivityRow parse_sensitivity(const json& j, const std::string& where) {
  SensitivityRow s;
  s.figure = req_string(j, where, "figure");
  s.unit = opt_string(j, where, "unit");
  s.min_value = req_number(j, where, "min_value");
  s.base_value = req_number(j, where, "base_value");
  s.max_value = req_number(j, where, "max_value");
  s.frame_ms_at_min = req_number(j, where, "frame_ms_at_min");
  s.frame_ms_at_base = req_number(j, where, "frame_ms_at_base");
  s.frame_ms_at_max = req_number(j, where, "frame_ms_at_max");
  return s;
}

std::vector<std::pair<std::string, std::string>> parse_labelled_paths(const json& j,
                                                                      const std::string& where) {
  std::vector<std::pair<std::string, std::string>> out;
  const json& items = array_at(j, where);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string at = index_path(where, i);
    out.emplace_back(req_string(items[i], at, "what"), req_string(items[i], at, "path"));
  }
  return out;
}

CropWindow parse_window(const json& j, const std::string& where) {
  CropWindow w;
  w.why = req_string(j, where, "why");
  w.x = req_int(j, where, "x");
  w.y = req_int(j, where, "y");
  w.size = req_int(j, where, "size");
  w.zoom_x = req_int(j, where, "zoom_x");
  w.zoom_y = req_int(j, where, "zoom_y");
  w.zoom_size = req_int(j, where, "zoom_size");
  w.zoom = req_int(j, where, "zoom");
  w.images = parse_labelled_paths(require(j, where, "images"), field_path(where, "images"));
  w.zoomed = parse_labelled_paths(require(j, where, "zoomed"), field_path(where, "zoomed"));
  return w;
}

ComparisonPanel parse_panel(const json& j, const std::string& where) {
  ComparisonPanel p;
  p.group = req_string(j, where, "group");
  p.chosen = req_string(j, where, "chosen");
  p.best = req_string(j, where, "best");
  p.reference_image = req_string(j, where, "reference_image");
  p.chosen_image = req_string(j, where, "chosen_image");
  p.best_image = req_string(j, where, "best_image");
  p.difference_gain = req_number(j, where, "difference_gain");
  p.colour_bar = req_string(j, where, "colour_bar");
  const std::string at = field_path(where, "windows");
  const json& windows = array_at(require(j, where, "windows"), at);
  for (std::size_t i = 0; i < windows.size(); ++i) {
    p.windows.push_back(parse_window(windows[i], index_path(at, i)));
  }
  return p;
}

json labelled_paths_json(const std::vector<std::pair<std::string, std::string>>& items) {
  json out = json::array();
  for (const auto& [what, path] : items) out.push_back({{"what", what}, {"path", path}});
  return out;
}

SweepTable parse_table(const json& j) {
  SweepTable t;
  t.device = req_string(j, "", "device");
  t.scene = req_string(j, "", "scene");
  t.resolution = req_string(j, "", "resolution");
  t.budget_ms = req_number(j, "", "budget_ms");
  const json& rows = array_at(require(j, "", "rows"), "rows");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    t.rows.push_back(parse_config(rows[i], index_path("rows", i)));
  }
  if (j.contains("heatmap") && !j["heatmap"].is_null()) {
    t.heatmap = parse_heatmap(j["heatmap"], "heatmap");
  }
  if (j.contains("assumptions")) t.assumptions = strings_at(j["assumptions"], "assumptions");
  if (j.contains("sensitivity")) {
    const json& sens = array_at(j["sensitivity"], "sensitivity");
    for (std::size_t i = 0; i < sens.size(); ++i) {
      t.sensitivity.push_back(parse_sensitivity(sens[i], index_path("sensitivity", i)));
    }
  }
  if (j.contains("panels")) {
    const json& panels = array_at(j["panels"], "panels");
    for (std::size_t i = 0; i < panels.size(); ++i) {
      t.panels.push_back(parse_panel(panels[i], index_path("panels", i)));
    }
  }
  return t;
}

// A modelled amount: a time in ms, an energy in mJ.
void check_amount(double v, const std::string& what, const std::string& where) {
  if (!std::isfinite(v) || v < 0.0) {
    throw ResultsError(where + ": must be a finite, non-negative " + what + ", got " +
                       std::to_string(v));
  }
}

void check_time(double ms, const std::string& where) {
  check_amount(ms, "time in ms", where);
}

// A row's estimate `name` and its range `name`_low..`name`_high.
void check_ranged(double low, double value, double high, const std::string& name,
                  const std::string& what, const std::string& where) {
  check_amount(value, what, where + "." + name);
  check_amount(low, what, where + "." + name + "_low");
  check_amount(high, what, where + "." + name + "_high");
  if (!(low <= value && value <= high)) {
    throw ResultsError(where + ": " + name + "_low <= " + name + " <= " + name +
                       "_high does not hold");
  }
}

// JSON has no NaN/infinity (nlohmann writes null), so a non-finite value would not round-trip.
void check_finite(double v, const std::string& where) {
  if (!std::isfinite(v)) throw ResultsError(where + ": must be a finite number");
}

// Image paths are links in report.html, resolved against the sweep directory.
void check_relative_path(const std::string& path, const std::string& where) {
  if (path.empty()) return;
  const std::filesystem::path p(path);
  const bool escapes =
      std::any_of(p.begin(), p.end(), [](const auto& part) { return part == ".."; });
  if (p.is_absolute() || escapes) {
    throw ResultsError(where + ": '" + path +
                       "' must be a relative path inside the sweep directory (no '..')");
  }
}

}  // namespace

void to_json(json& j, const PassCost& v) {
  j = json{{"name", v.name},
           {"ms", v.ms},
           {"bottleneck", v.bottleneck},
           {"dram_bytes_by_cause", v.dram_bytes_by_cause},
           {"ta_start_ms", v.ta_start_ms},
           {"ta_end_ms", v.ta_end_ms},
           {"render_start_ms", v.render_start_ms},
           {"render_end_ms", v.render_end_ms}};
}

void to_json(json& j, const ProgramCost& v) {
  j = json{{"pass", v.pass},
           {"program", v.program},
           {"fragments", v.fragments},
           {"vector_ops", v.vector_ops},
           {"scalar_ops", v.scalar_ops},
           {"transcendental_ops", v.transcendental_ops},
           {"texture_reads_independent", v.texture_reads_independent},
           {"texture_reads_dependent", v.texture_reads_dependent}};
}

void to_json(json& j, const ConfigResult& v) {
  j = json{{"id", v.id},
           {"label", v.label},
           {"knobs", v.knobs},
           {"frame_ms", v.frame_ms},
           {"frame_ms_low", v.frame_ms_low},
           {"frame_ms_high", v.frame_ms_high},
           {"fps", v.fps},
           {"dram_bytes", v.dram_bytes},
           {"energy_mj", v.energy_mj},
           {"energy_mj_low", v.energy_mj_low},
           {"energy_mj_high", v.energy_mj_high},
           {"passes", v.passes},
           {"programs", v.programs},
           {"quality", v.quality},
           {"frame_image", v.frame_image},
           {"error_image", v.error_image},
           {"reference_image", v.reference_image},
           {"visible_vs_reference", v.visible_vs_reference},
           {"group", v.group},
           {"vs_finest", v.vs_finest ? json(*v.vs_finest) : json(nullptr)},
           {"vs_best", v.vs_best ? json(*v.vs_best) : json(nullptr)}};
  if (v.sequence) j["sequence"] = *v.sequence;
}

void to_json(json& j, const FrameComparison& v) {
  j = json{{"against", v.against},
           {"flip_mean", v.flip_mean},
           {"flip_p99", v.flip_p99},
           {"visible_px", v.visible_px},
           {"visible", v.visible}};
}
void from_json(const json& j, FrameComparison& v) {
  v = parse_comparison(j, "comparison");
}

void to_json(json& j, const TileHeatmap& v) {
  j = json{{"tiles_x", v.tiles_x},       {"tiles_y", v.tiles_y},
           {"tile_size", v.tile_size},   {"ms", v.ms},
           {"bottleneck", v.bottleneck}, {"pass_name", v.pass_name},
           {"config_id", v.config_id}};
}

void to_json(json& j, const SensitivityRow& v) {
  j = json{{"figure", v.figure},
           {"unit", v.unit},
           {"min_value", v.min_value},
           {"base_value", v.base_value},
           {"max_value", v.max_value},
           {"frame_ms_at_min", v.frame_ms_at_min},
           {"frame_ms_at_base", v.frame_ms_at_base},
           {"frame_ms_at_max", v.frame_ms_at_max}};
}

void to_json(json& j, const SweepTable& v) {
  j = json{{"device", v.device},
           {"scene", v.scene},
           {"resolution", v.resolution},
           {"budget_ms", v.budget_ms},
           {"rows", v.rows},
           {"heatmap", v.heatmap ? json(*v.heatmap) : json(nullptr)},
           {"assumptions", v.assumptions},
           {"sensitivity", v.sensitivity},
           {"panels", v.panels}};
}

void to_json(json& j, const CropWindow& v) {
  j = json{{"why", v.why},
           {"x", v.x},
           {"y", v.y},
           {"size", v.size},
           {"zoom_x", v.zoom_x},
           {"zoom_y", v.zoom_y},
           {"zoom_size", v.zoom_size},
           {"zoom", v.zoom},
           {"images", labelled_paths_json(v.images)},
           {"zoomed", labelled_paths_json(v.zoomed)}};
}
void from_json(const json& j, CropWindow& v) {
  v = parse_window(j, "window");
}

void to_json(json& j, const ComparisonPanel& v) {
  j = json{{"group", v.group},
           {"chosen", v.chosen},
           {"best", v.best},
           {"reference_image", v.reference_image},
           {"chosen_image", v.chosen_image},
           {"best_image", v.best_image},
           {"difference_gain", v.difference_gain},
           {"colour_bar", v.colour_bar},
           {"windows", v.windows}};
}
void from_json(const json& j, ComparisonPanel& v) {
  v = parse_panel(j, "panel");
}

void from_json(const json& j, PassCost& v) {
  v = parse_pass(j, "pass");
}
void from_json(const json& j, ConfigResult& v) {
  v = parse_config(j, "row");
}
void from_json(const json& j, TileHeatmap& v) {
  v = parse_heatmap(j, "heatmap");
}
void from_json(const json& j, SensitivityRow& v) {
  v = parse_sensitivity(j, "sensitivity");
}

void from_json(const json& j, SweepTable& v) {
  SweepTable t = parse_table(j);
  validate_sweep_table(t);
  v = std::move(t);
}

void validate_sweep_table(const SweepTable& t) {
  if (!std::isfinite(t.budget_ms) || t.budget_ms <= 0.0) {
    throw ResultsError("budget_ms: must be a positive number of ms, got " +
                       std::to_string(t.budget_ms));
  }
  std::set<std::string> ids;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const ConfigResult& r = t.rows[i];
    const std::string where = index_path("rows", i);
    if (r.id.empty()) throw ResultsError(where + ".id: must not be empty");
    if (!ids.insert(r.id).second) throw ResultsError(where + ".id: duplicate id '" + r.id + "'");
    check_ranged(r.frame_ms_low, r.frame_ms, r.frame_ms_high, "frame_ms", "time in ms", where);
    check_ranged(r.energy_mj_low, r.energy_mj, r.energy_mj_high, "energy_mj", "energy in mJ",
                 where);
    check_finite(r.fps, where + ".fps");
    check_finite(r.dram_bytes, where + ".dram_bytes");
    for (const auto& [name, value] : r.quality) check_finite(value, where + ".quality." + name);
    check_relative_path(r.frame_image, where + ".frame_image");
    check_relative_path(r.error_image, where + ".error_image");
    check_relative_path(r.reference_image, where + ".reference_image");
    for (const auto& [name, c] : {std::pair{"vs_finest", &r.vs_finest}, {"vs_best", &r.vs_best}}) {
      if (!*c) continue;
      const std::string at = where + "." + name;
      check_finite((*c)->flip_mean, at + ".flip_mean");
      check_finite((*c)->flip_p99, at + ".flip_p99");
      check_finite((*c)->visible_px, at + ".visible_px");
    }
    for (std::size_t p = 0; p < r.passes.size(); ++p) {
      const PassCost& pass = r.passes[p];
      const std::string at = index_path(where + ".passes", p);
      check_time(pass.ms, at + ".ms");
      for (const auto& [name, value] : {std::pair{"ta_start_ms", pass.ta_start_ms},
                                        {"ta_end_ms", pass.ta_end_ms},
                                        {"render_start_ms", pass.render_start_ms},
                                        {"render_end_ms", pass.render_end_ms}}) {
        check_time(value, at + "." + name);
      }
      if (pass.ta_end_ms < pass.ta_start_ms || pass.render_end_ms < pass.render_start_ms) {
        throw ResultsError(at + ": a stage ends before it starts");
      }
    }
  }
  if (t.heatmap) {
    const TileHeatmap& h = *t.heatmap;
    if (h.tiles_x <= 0 || h.tiles_y <= 0 || h.tile_size <= 0) {
      throw ResultsError("heatmap: tiles_x, tiles_y and tile_size must be positive");
    }
    const std::size_t n = static_cast<std::size_t>(h.tiles_x) * static_cast<std::size_t>(h.tiles_y);
    if (h.ms.size() != n) {
      throw ResultsError("heatmap.ms: expected tiles_x * tiles_y = " + std::to_string(n) +
                         " values, got " + std::to_string(h.ms.size()));
    }
    if (!h.bottleneck.empty() && h.bottleneck.size() != n) {
      throw ResultsError("heatmap.bottleneck: expected " + std::to_string(n) +
                         " entries (or none), got " + std::to_string(h.bottleneck.size()));
    }
    for (std::size_t i = 0; i < n; ++i) check_time(h.ms[i], index_path("heatmap.ms", i));
  }
  for (std::size_t p = 0; p < t.panels.size(); ++p) {
    const ComparisonPanel& panel = t.panels[p];
    const std::string where = index_path("panels", p);
    for (const auto& [name, path] : {std::pair{".reference_image", &panel.reference_image},
                                     {".chosen_image", &panel.chosen_image},
                                     {".best_image", &panel.best_image},
                                     {".colour_bar", &panel.colour_bar}}) {
      check_relative_path(*path, where + name);
    }
    for (const CropWindow& w : panel.windows) {
      for (const auto* list : {&w.images, &w.zoomed}) {
        for (const auto& [what, path] : *list) check_relative_path(path, where + ".windows");
      }
    }
  }
}

SweepTable read_sweep_json(const std::string& path) {
  const std::string text = io::read_regular_file(path, "sweep results");
  const json j = io::parse_json(text, "sweep results", path);
  try {
    return j.get<SweepTable>();
  } catch (const ResultsError& e) {
    throw ResultsError(path + ": " + e.what());
  }
}

std::string dominant_bottleneck(const ConfigResult& row) {
  auto it = std::max_element(row.passes.begin(), row.passes.end(),
                             [](const PassCost& a, const PassCost& b) { return a.ms < b.ms; });
  return it == row.passes.end() ? std::string() : it->bottleneck;
}

std::vector<PassCost> merged_passes(const ConfigResult& row) {
  std::vector<PassCost> out;
  std::vector<double> costliest;  // ms of the instance whose bottleneck out[i] carries
  for (const PassCost& p : row.passes) {
    auto it =
        std::find_if(out.begin(), out.end(), [&](const PassCost& m) { return m.name == p.name; });
    if (it == out.end()) {
      out.push_back(p);
      costliest.push_back(p.ms);
      continue;
    }
    const std::size_t i = static_cast<std::size_t>(it - out.begin());
    it->ms += p.ms;
    for (const auto& [cause, bytes] : p.dram_bytes_by_cause)
      it->dram_bytes_by_cause[cause] += bytes;
    if (p.ms > costliest[i]) {
      costliest[i] = p.ms;
      it->bottleneck = p.bottleneck;
    }
  }
  return out;
}

std::string knob_value(const ConfigResult& row, const std::string& knob) {
  auto it = row.knobs.find(knob);
  return it == row.knobs.end() ? std::string() : it->second;
}

}  // namespace skinsim::results
