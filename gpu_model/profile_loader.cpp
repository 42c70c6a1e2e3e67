#include "gpu_model/profile_loader.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "gpu_model/error.h"
#include "io/read_file.h"

namespace skinsim::gpu_model {
namespace {

namespace fs = std::filesystem;

const char* type_name(toml::node_type t) {
  switch (t) {
    case toml::node_type::table:
      return "table";
    case toml::node_type::array:
      return "array";
    case toml::node_type::string:
      return "string";
    case toml::node_type::integer:
      return "integer";
    case toml::node_type::floating_point:
      return "float";
    case toml::node_type::boolean:
      return "boolean";
    default:
      return "date/time";
  }
}

// Builds errors that name the file, the dotted field and the line.
class Reporter {
 public:
  explicit Reporter(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& field, const toml::node* node,
                         const std::string& what) const {
    std::string where = file_;
    if (node != nullptr && node->source().begin.line > 0) {
      where += fmt::format(":{}", node->source().begin.line);
    }
    throw ProfileError(fmt::format("{}: field '{}': {}", where, field, what));
  }

  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

const toml::table& require_table(const Reporter& r, const toml::table& parent,
                                 const std::string& key, const std::string& path) {
  const toml::node* node = parent.get(key);
  if (node == nullptr) r.fail(path, nullptr, "missing");
  if (!node->is_table()) {
    r.fail(path, node, fmt::format("must be a table, got {}", type_name(node->type())));
  }
  return *node->as_table();
}

std::string require_string(const Reporter& r, const toml::table& parent, const std::string& key,
                           const std::string& path) {
  const toml::node* node = parent.get(key);
  if (node == nullptr) r.fail(path, nullptr, "missing");
  if (!node->is_string()) {
    r.fail(path, node, fmt::format("must be a string, got {}", type_name(node->type())));
  }
  std::string s = node->as_string()->get();
  if (s.empty()) r.fail(path, node, "must not be empty");
  return s;
}

double require_number(const Reporter& r, const toml::node* node, const std::string& path) {
  if (node == nullptr) r.fail(path, nullptr, "missing");
  if (node->is_integer()) return static_cast<double>(node->as_integer()->get());
  if (node->is_floating_point()) return node->as_floating_point()->get();
  r.fail(path, node, fmt::format("must be a number, got {}", type_name(node->type())));
}

void check_unknown_keys(const Reporter& r, const toml::table& table,
                        const std::set<std::string>& known, const std::string& prefix) {
  for (const auto& [key, node] : table) {
    if (known.count(std::string(key.str())) == 0) {
      std::string path =
          prefix.empty() ? std::string(key.str()) : fmt::format("{}.{}", prefix, key.str());
      r.fail(path, &node, "unknown key");
    }
  }
}

std::string describe(const FigureBounds& b, const char* unit) {
  const char* what = b.power_of_two ? "a power of two" : b.integer ? "an integer" : "a number";
  return fmt::format("must be {} in [{}, {}]{}{}", what, b.min, b.max, *unit ? " " : "", unit);
}

// Checks a value or range endpoint against the figure's bounds (FigureSpec).
void check_bounds(const Reporter& r, const toml::node* node, const std::string& path,
                  const FigureSpec& spec, double v) {
  const FigureBounds& b = spec.bounds;
  const bool in_range = v >= b.min && v <= b.max;  // false for NaN
  const bool integral = in_range && v == std::floor(v);
  const bool ok = in_range && (!b.integer || integral) &&
                  (!b.power_of_two || std::has_single_bit(static_cast<std::uint64_t>(v)));
  if (!ok) r.fail(path, node, fmt::format("{}, got {}", describe(b, spec.unit), v));
}

Confidence parse_confidence(const Reporter& r, const toml::table& fig, const std::string& path) {
  const std::string c = require_string(r, fig, "confidence", path);
  if (c == "low") return Confidence::kLow;
  if (c == "medium") return Confidence::kMedium;
  if (c == "high") return Confidence::kHigh;
  if (c == "certain") return Confidence::kCertain;
  r.fail(path, fig.get("confidence"),
         fmt::format("must be one of low, medium, high, certain; got '{}'", c));
}

GpuClass parse_gpu_class(const Reporter& r, const toml::table& device) {
  const std::string c = require_string(r, device, "class", "device.class");
  for (GpuClass k : {GpuClass::kTbdr, GpuClass::kTilerEarlyZ, GpuClass::kBinning}) {
    if (c == gpu_class_name(k)) return k;
  }
  r.fail("device.class", device.get("class"),
         fmt::format("must be one of tbdr, tiler-early-z, binning; got '{}'", c));
}

Figure parse_figure(const Reporter& r, const toml::table& fig, const FigureSpec& spec) {
  const std::string base = spec.path;
  check_unknown_keys(r, fig, {"value", "range", "confidence", "source"}, base);
  Figure f;
  const std::string value_path = base + ".value";
  f.value = require_number(r, fig.get("value"), value_path);
  check_bounds(r, fig.get("value"), value_path, spec, f.value);
  f.source = require_string(r, fig, "source", base + ".source");
  f.confidence = parse_confidence(r, fig, base + ".confidence");
  f.min = f.max = f.value;

  const std::string range_path = base + ".range";
  const toml::node* range = fig.get("range");
  if (range == nullptr) {
    // An uncertain figure without a range would escape the sensitivity analysis.
    if (f.confidence == Confidence::kLow) {
      r.fail(range_path, nullptr, "missing (required when confidence is low)");
    }
    return f;
  }
  const toml::array* arr = range->as_array();
  if (arr == nullptr || arr->size() != 2) {
    r.fail(range_path, range, "must be an array [min, max]");
  }
  f.min = require_number(r, arr->get(0), range_path + "[0]");
  f.max = require_number(r, arr->get(1), range_path + "[1]");
  check_bounds(r, arr->get(0), range_path + "[0]", spec, f.min);
  check_bounds(r, arr->get(1), range_path + "[1]", spec, f.max);
  if (!(f.min <= f.value && f.value <= f.max)) {
    r.fail(range_path, range,
           fmt::format("must satisfy min <= value <= max, got [{}, {}] with value {}", f.min, f.max,
                       f.value));
  }
  f.has_range = true;
  return f;
}

// sim::Gpu renders square tiles, and sensitivity varies one figure at a time, so a range on
// one axis would ask for a non-square tile.
void check_square_tiles(const Reporter& r, const toml::table& root, const DeviceProfile& p) {
  if (p.tile_height.value != p.tile_width.value) {
    r.fail(
        "tile.height.value", root.at_path("tile.height.value").node(),
        fmt::format("must equal tile.width.value ({}), got {}: the emulator renders square tiles",
                    p.tile_width.value, p.tile_height.value));
  }
  for (const char* path : {"tile.width", "tile.height"}) {
    const std::string range_path = std::string(path) + ".range";
    const toml::node* range = root.at_path(range_path).node();
    if (range != nullptr) {
      r.fail(range_path, range,
             "not supported: the emulator renders square tiles, so the tile size cannot be "
             "varied one axis at a time");
    }
  }
}

// Why sim::TextureCache would refuse a cache shape.
struct CacheProblem {
  const char* field = nullptr;  // the figure to name; nullptr when the cache builds
  std::string what;
};

// bytes, line bytes, ways, set hash, in the order of the [texture] cache figures.
CacheProblem cache_problem(const std::array<double, 4>& v) {
  // The emulator builds a set-associative cache: whole lines in whole sets.
  const double set_bytes = v[1] * v[2];
  if (std::fmod(v[0], set_bytes) != 0.0) {
    return {
        "texture.cache_bytes",
        fmt::format("cache_bytes {} is not a multiple of cache_line_bytes x cache_ways = {} x {}",
                    v[0], v[1], v[2])};
  }
  // XOR folding works on the index bit field, so it needs a power-of-two set count
  // (sim::SetIndex::kXorFold).
  const auto sets = static_cast<std::uint64_t>(v[0] / set_bytes);
  if (v[3] != 0.0 && !std::has_single_bit(sets)) {
    return {
        "texture.cache_set_hash",
        fmt::format("XOR-folded set index (cache_set_hash 1) needs a power-of-two set count, "
                    "but cache_bytes / (cache_line_bytes x cache_ways) = {} / ({} x {}) = {} sets",
                    v[0], v[1], v[2], sets)};
  }
  return {};
}

// The texture cache must build with the base figures and with each range endpoint that
// sensitivity substitutes (one figure at a time, the others at their values).
void check_texture_cache(const Reporter& r, const toml::table& root, const DeviceProfile& p) {
  const std::array<std::pair<const char*, const Figure*>, 4> figures = {{
      {"texture.cache_bytes", &p.texture_cache_bytes},
      {"texture.cache_line_bytes", &p.texture_cache_line_bytes},
      {"texture.cache_ways", &p.texture_cache_ways},
      {"texture.cache_set_hash", &p.texture_cache_set_hash},
  }};
  std::array<double, 4> base{};
  for (std::size_t i = 0; i < figures.size(); ++i) base[i] = figures[i].second->value;
  const auto fail = [&](const std::string& path, const std::string& what) {
    r.fail(path, root.at_path(path).node(), what);
  };
  if (const CacheProblem problem = cache_problem(base); problem.field != nullptr) {
    fail(std::string(problem.field) + ".value", problem.what);
  }
  for (std::size_t i = 0; i < figures.size(); ++i) {
    const Figure& f = *figures[i].second;
    if (!f.has_range) continue;
    const std::string range = std::string(figures[i].first) + ".range";
    for (const auto& [endpoint, index] : {std::pair{f.min, "[0]"}, std::pair{f.max, "[1]"}}) {
      std::array<double, 4> varied = base;
      varied[i] = endpoint;
      const CacheProblem problem = cache_problem(varied);
      if (problem.field != nullptr) fail(range + index, problem.what);
    }
  }
}

DeviceProfile parse_root(const Reporter& r, const toml::table& root) {
  DeviceProfile p;
  p.source_path = r.file();
  p.name = fs::path(r.file()).stem().string();

  // Section names and their keys, derived from the figure table.
  std::set<std::string> sections = {"device"};
  for (const FigureSpec& spec : figure_specs()) {
    const std::string path = spec.path;
    sections.insert(path.substr(0, path.find('.')));
  }
  check_unknown_keys(r, root, sections, "");

  const toml::table& device = require_table(r, root, "device", "device");
  check_unknown_keys(r, device, {"name", "soc", "gpu", "class"}, "device");
  p.device = require_string(r, device, "name", "device.name");
  p.soc = require_string(r, device, "soc", "device.soc");
  p.gpu = require_string(r, device, "gpu", "device.gpu");
  p.gpu_class = parse_gpu_class(r, device);

  for (const std::string& section : sections) {
    if (section == "device") continue;
    const toml::table& table = require_table(r, root, section, section);
    std::set<std::string> keys;
    for (const FigureSpec& spec : figure_specs()) {
      const std::string path = spec.path;
      if (path.substr(0, path.find('.')) == section) keys.insert(path.substr(path.find('.') + 1));
    }
    check_unknown_keys(r, table, keys, section);
  }

  for (const FigureSpec& spec : figure_specs()) {
    const std::string path = spec.path;
    const std::string section = path.substr(0, path.find('.'));
    const std::string key = path.substr(path.find('.') + 1);
    const toml::node* node = root.get(section)->as_table()->get(key);
    if (node == nullptr) r.fail(path, nullptr, "missing");
    if (!node->is_table()) {
      r.fail(path, node,
             fmt::format("must be a table with value, source, confidence (and range), got {}",
                         type_name(node->type())));
    }
    const toml::table& fig = *node->as_table();
    p.*spec.member = parse_figure(r, fig, spec);
  }

  check_square_tiles(r, root, p);
  check_texture_cache(r, root, p);
  // Deferred HSR shades only what is visible, whatever the draw order (PowerVR Architecture
  // Guide); anything else describes another class.
  if (p.gpu_class == GpuClass::kTbdr &&
      (p.hsr_overdraw_removed.value != 1.0 || p.hsr_overdraw_removed.has_range)) {
    r.fail("hsr.overdraw_removed", root.at_path("hsr.overdraw_removed").node(),
           "must be 1 without a range on a tbdr device (deferred HSR removes all overdraw)");
  }
  return p;
}

}  // namespace

DeviceProfile parse_device_profile(std::string_view toml_text, const std::string& file_name) {
  const Reporter reporter(file_name);
  toml::table root;
  try {
    root = toml::parse(toml_text, file_name);
  } catch (const toml::parse_error& e) {
    throw ProfileError(fmt::format("{}:{}:{}: TOML syntax error: {}", file_name,
                                   e.source().begin.line, e.source().begin.column,
                                   e.description()));
  }
  return parse_root(reporter, root);
}

std::vector<std::string> list_devices(const std::string& data_dir) {
  const fs::path dir = fs::path(data_dir) / "devices";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw ProfileError(fmt::format("{}: device profile directory does not exist", dir.string()));
  }
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".toml") {
      names.push_back(entry.path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

DeviceProfile load_device_profile(const std::string& name_or_path, const std::string& data_dir) {
  const bool is_path =
      name_or_path.find('/') != std::string::npos || fs::path(name_or_path).extension() == ".toml";
  const fs::path path =
      is_path ? fs::path(name_or_path) : fs::path(data_dir) / "devices" / (name_or_path + ".toml");
  if (!fs::exists(path)) {
    std::string hint;
    if (!is_path) {
      std::string names;
      try {
        for (const std::string& n : list_devices(data_dir))
          names += (names.empty() ? "" : ", ") + n;
      } catch (const ProfileError&) {
        names = "none";
      }
      hint = fmt::format(" (known devices: {})", names.empty() ? "none" : names);
    }
    throw ProfileError(
        fmt::format("{}: cannot open device profile '{}'{}", path.string(), name_or_path, hint));
  }
  return parse_device_profile(io::read_regular_file(path, "device profile"), path.string());
}

DeviceCatalog load_device_catalog(const std::string& data_dir) {
  DeviceCatalog catalog;
  for (const std::string& name : list_devices(data_dir)) {
    try {
      catalog.profiles.push_back(load_device_profile(name, data_dir));
    } catch (const UserError& e) {  // ProfileError, or the file could not be read
      catalog.problems.push_back(e.what());
    }
  }
  return catalog;
}

}  // namespace skinsim::gpu_model
