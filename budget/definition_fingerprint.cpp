#include "budget/definition_fingerprint.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <vector>

#include "budget/device_fingerprint.h"

namespace skinsim::budget {

namespace {

std::string relative_to(const std::string& path, const std::filesystem::path& budget_file) {
  if (path.empty() || path == "builtin" || path.find('/') == std::string::npos) return path;
  return std::filesystem::path(path).lexically_relative(budget_file.parent_path()).string();
}

}  // namespace

std::string definition_fingerprint(const Budget& budget, const std::filesystem::path& budget_file) {
  std::string text = fmt::format(
      "device={}\nscene.path={}\nscene.head_triangles={}\nscene.texture_size={}\n"
      "scene.skin_materials={}\nscene.units_per_mm={}\n",
      relative_to(budget.device, budget_file), relative_to(budget.scene.path, budget_file),
      budget.scene.head_triangles, budget.scene.texture_size,
      fmt::join(budget.scene.skin_materials, ","), budget.scene.units_per_mm);
  // By name, so that reordering the knob table changes no fingerprint.
  std::vector<std::string> knobs = pipeline::config_field_names();
  std::sort(knobs.begin(), knobs.end());
  for (const std::string& knob : knobs) {
    text += fmt::format("{}={}\n", knob, pipeline::get_config_field(budget.config, knob));
  }
  if (const std::optional<driver::Sequence>& s = budget.sequence) {  // absent: as before
    text += fmt::format("sequence={}\nframes={}\nfps={}\nloops={}\n", s->name, s->frames, s->fps,
                        s->loops);
    for (const driver::SequenceTrack& t : s->tracks) {
      text += fmt::format("track={},{},{},{},{}\n", t.knob, t.relative, t.from, t.to, t.by);
    }
  }
  return fingerprint(text);
}

}  // namespace skinsim::budget
