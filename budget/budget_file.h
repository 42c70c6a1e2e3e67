// Budget files (TOML): each [[budget]] names a device, a scene, a resolution and pipeline
// knobs, and limits metrics of the frame they produce. Format: docs/budgets.md.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "budget/limit.h"
#include "driver/frame/scene_source.h"
#include "driver/sequence/sequence.h"
#include "pipeline/config.h"

namespace skinsim::budget {

struct Budget {
  std::string name;
  int line = 0;        // of its [[budget]] header
  std::string device;  // a shipped profile name or a .toml path (resolved against the file)
  driver::SceneSource scene;
  pipeline::PipelineConfig config;  // knobs set through pipeline::set_config_field
  double target_fps = 60.0;         // the frame rate the failure messages measure against
  // `sequence` (a preset or a sequence file, relative to the budget file) with `frames` and
  // `fps`: the budget measures every frame, its frame_ms.<stat> limits the distribution and
  // the other limits the worst frame (driver/sequence/sequence.h).
  std::optional<driver::Sequence> sequence;
  std::vector<Limit> limits;  // in file order

  bool needs_quality() const;
  bool needs_baseline() const;
};

struct BudgetFile {
  std::filesystem::path path;
  std::filesystem::path baseline_path;  // `baseline = ...`, else <stem>.baseline.json beside it
  std::vector<Budget> budgets;
};

// Reads and validates a budget file. Throws BudgetError naming the file and line on any
// problem: malformed TOML, unknown or mistyped keys, a bad knob value, a malformed limit, a
// limit on a metric kind that does not exist, duplicate budget names.
BudgetFile load_budget_file(const std::filesystem::path& path);
// The same from text; `path` is used in messages and to resolve relative paths.
BudgetFile parse_budget_file(const std::string& text, const std::filesystem::path& path);

}  // namespace skinsim::budget
