// Option groups shared by the subcommands, bound to the parameter sets they fill.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "driver/frame/scene_source.h"
#include "driver/truth/truth_judge.h"
#include "gpu_model/device_profile.h"
#include "pipeline/config.h"

namespace skinsim::app {

struct DeviceOptions {
  std::string device = "ipad4";
  std::string data_dir;  // filled with the default data directory when empty
  int threads = 0;
};

void add_device_options(CLI::App& cmd, DeviceOptions& options);
void add_scene_options(CLI::App& cmd, driver::SceneSource& source);
// One option per pipeline knob, and --set KNOB=VALUE (as `sweep --set`) for any knob by its
// name; each value goes through the knob's own parser, so the CLI, sweep files and budgets
// validate identically.
void add_pipeline_options(CLI::App& cmd, pipeline::PipelineConfig& config);

// --truth-samples and --truth-seed (`skinsim truth`'s --samples and --seed): which cached truth
// `--truth cached` takes (driver::TruthChoice).
void add_truth_choice_options(CLI::App& cmd, driver::TruthChoice& choice);

// "knob=value" as --set takes it, split at the first '='; throws UserError naming `option`.
struct KnobAssignment {
  std::string knob;
  std::string value;
};
KnobAssignment parse_knob_assignment(const std::string& text, const std::string& option);

// Validators for numeric options. CLI11 alone accepts "0x10", " 1" and "nan"; these accept
// only what skinsim::parse_integer / parse_real accept, within range.
CLI::Validator integer_in(int lo, int hi);
CLI::Validator positive_real(double max);
CLI::Validator non_negative_real(double max);

// The shipped data directory: $SKINSIM_DATA_DIR, else the source tree's data/.
std::string default_data_dir();

// The profile --device names, from --data-dir or the default data directory.
gpu_model::DeviceProfile load_device(const DeviceOptions& options);

}  // namespace skinsim::app
