#include "driver/sweep/run_compare.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <set>

#include "driver/sweep/crop_windows.h"
#include "driver/sweep/image_diff.h"
#include "driver/sweep/result_values.h"
#include "io/json_input.h"

namespace skinsim::driver {

namespace fs = std::filesystem;

namespace {

enum class Kind { kRun, kSweep };

const char* kind_name(Kind k) {
  return k == Kind::kRun ? "run" : "sweep";
}

// A directory holding result.json (a run) or results.json (a sweep); either file itself
// stands for its directory.
std::pair<fs::path, Kind> locate(const fs::path& given, const char* side) {
  fs::path dir = given;
  if (fs::is_regular_file(given) &&
      (given.filename() == "result.json" || given.filename() == "results.json")) {
    dir = given.parent_path().empty() ? fs::path(".") : given.parent_path();
  }
  if (!fs::is_directory(dir)) {
    throw io::InputError(
        fmt::format("{} {}: no such directory (give a run directory holding result.json or a sweep "
                    "directory holding results.json)",
                    side, given.string()));
  }
  if (fs::exists(dir / "result.json")) return {dir, Kind::kRun};
  if (fs::exists(dir / "results.json")) return {dir, Kind::kSweep};
  throw io::InputError(fmt::format(
      "{} {}: neither result.json (a run, from `skinsim run --out`) nor results.json (a "
      "sweep) is in it",
      side, dir.string()));
}

nlohmann::json read_result(const fs::path& dir) {
  const fs::path path = dir / "result.json";
  nlohmann::json j = io::read_json_file(path, "run result");
  for (const char* field : {"config", "timing", "counters"}) {
    if (!j.is_object() || !j.contains(field)) {
      throw io::InputError(
          fmt::format("{}: no \"{}\" (not a skinsim run's result.json)", path.string(), field));
    }
  }
  if (!j["config"].is_object())
    throw io::InputError(path.string() + ": \"config\" is not an object");
  return j;
}

std::string setting_text(const nlohmann::json* j) {
  if (!j) return "";
  return j->is_string() ? j->get<std::string>() : j->dump();
}

// The config's knobs, then the device and scene, that differ.
std::vector<reports::SettingChange> setting_changes(const nlohmann::json& a,
                                                    const nlohmann::json& b) {
  std::set<std::string> knobs;
  for (const auto& [k, v] : a.at("config").items()) knobs.insert(k);
  for (const auto& [k, v] : b.at("config").items()) knobs.insert(k);
  std::vector<reports::SettingChange> changes;
  const auto add = [&](const std::string& name, const nlohmann::json& ja, const nlohmann::json& jb,
                       const std::string& key) {
    const std::string va = setting_text(ja.contains(key) ? &ja[key] : nullptr);
    const std::string vb = setting_text(jb.contains(key) ? &jb[key] : nullptr);
    if (va != vb) changes.push_back({name, va, vb});
  };
  for (const std::string& k : knobs) add(k, a.at("config"), b.at("config"), k);
  for (const char* k : {"device", "scene"}) add(k, a, b, k);
  return changes;
}

// Every PNG of either run but the frame, sorted by name.
std::vector<reports::ImageChange> other_images(const fs::path& a, const fs::path& b,
                                               const fs::path& out_dir) {
  std::set<std::string> names;
  for (const fs::path& dir : {a, b}) {
    for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      if (e.is_regular_file() && e.path().extension() == ".png" && name != "frame.png") {
        names.insert(name);
      }
    }
  }
  std::vector<reports::ImageChange> changes;
  for (const std::string& name : names) {
    const bool in_a = fs::exists(a / name), in_b = fs::exists(b / name);
    reports::ImageChange change =
        in_a && in_b ? diff_pixels(a / name, b / name) : reports::ImageChange{};
    change.name = name;
    if (in_a) change.a_image = link_from(out_dir, a / name);
    if (in_b) change.b_image = link_from(out_dir, b / name);
    changes.push_back(std::move(change));
  }
  return changes;
}

reports::Comparison compare_runs(const fs::path& a, const fs::path& b,
                                 const reports::Tolerances& tolerances, const fs::path& out_dir) {
  const nlohmann::json ja = read_result(a);
  const nlohmann::json jb = read_result(b);
  reports::Comparison c;
  c.kind = "run";
  c.changes = setting_changes(ja, jb);
  reports::ConfigDiff run;
  run.id = "run";
  compare_values(numeric_values(ja), numeric_values(jb), tolerances, run);
  run.image =
      diff_frames(a / "frame.png", b / "frame.png", nullptr, "the whole frame", out_dir, "frame");
  run.image->a_image = link_from(out_dir, a / "frame.png");
  run.image->b_image = link_from(out_dir, b / "frame.png");
  run.other_images = other_images(a, b, out_dir);
  c.configs.push_back(std::move(run));
  return c;
}

}  // namespace

std::string link_from(const fs::path& dir, const fs::path& path) {
  if (dir.empty()) return path.string();
  return fs::relative(fs::absolute(path), fs::absolute(dir)).generic_string();
}

reports::Comparison compare_outputs(const fs::path& a, const fs::path& b,
                                    const reports::Tolerances& tolerances,
                                    const fs::path& out_dir) {
  const auto [dir_a, kind_a] = locate(a, "A");
  const auto [dir_b, kind_b] = locate(b, "B");
  if (kind_a != kind_b) {
    throw UserError(fmt::format("A {} is a {} and B {} is a {}: compare two runs or two sweeps",
                                a.string(), kind_name(kind_a), b.string(), kind_name(kind_b)));
  }
  reports::Comparison c = kind_a == Kind::kRun ? compare_runs(dir_a, dir_b, tolerances, out_dir)
                                               : compare_sweeps(dir_a, dir_b, tolerances, out_dir);
  c.a = a.string();
  c.b = b.string();
  c.tolerances = tolerances;
  c.difference_gain = kDifferenceGain;
  const bool any_difference_image = std::any_of(
      c.configs.begin(), c.configs.end(),
      [](const reports::ConfigDiff& d) { return d.image && !d.image->difference_image.empty(); });
  if (any_difference_image) {
    c.colour_bar = "colour_bar.png";
    write_colour_bar(out_dir / c.colour_bar);
  }
  return c;
}

}  // namespace skinsim::driver
