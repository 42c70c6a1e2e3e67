// `skinsim validate MEASURED.csv`: the modelled frame of a configuration (the same device,
// scene and knob options as `run`) against per-pass GPU times measured on a device: model ms,
// its range over the profile's uncertain figures, measured ms, error, in range or not. Exit 0
// when every compared time is inside its range, 1 when one is outside, 2 on bad input. It
// never changes a profile. See docs/validation.md.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/cli_options.h"
#include "app/commands.h"
#include "driver/frame/frame_job.h"
#include "driver/validate/validate_compare.h"
#include "driver/validate/validate_measurements.h"
#include "io/atomic_file.h"
#include "pipeline/technique.h"

namespace skinsim::app {

namespace {

struct ValidateCliOptions {
  std::string measured;
  DeviceOptions device;
  driver::SceneSource scene;
  pipeline::PipelineConfig config;
  std::string json;  // none: the terminal table only
  bool allow_unknown_passes = false;
};

int validate(const ValidateCliOptions& o) {
  if (!o.json.empty()) io::require_not_input(o.json, "--json", o.measured, "the measurements");
  // The measurements first: a bad file fails before any rendering.
  const driver::Measurements measured = driver::read_measurements(o.measured);
  const gpu_model::DeviceProfile device = load_device(o.device);
  const pipeline::PipelineConfig config = driver::resolve_config(o.config, device);

  driver::FrameJob job;
  job.device = &device;
  job.config = config;
  job.scene = o.scene;
  job.scene.warn = [](const std::string& message) {
    fmt::print(stderr, "skinsim validate: warning: {}\n", message);
  };
  job.threads = o.device.threads;
  job.reference = false;  // timing only
  const driver::FrameJobResult frame_job = driver::run_frame_job(job);
  const driver::FrameResult& result = frame_job.frame;

  driver::ValidateOptions options;
  options.allow_unknown_passes = o.allow_unknown_passes;
  driver::Validation v = driver::compare_measurements(
      measured, result.timing, driver::row_ms_ranges(result.output.passes, device), result.range,
      options);
  std::vector<std::string> knobs;
  for (const std::string& knob : pipeline::summary_knobs(config)) {
    if (!pipeline::knob_applies(config, knob)) continue;
    knobs.push_back(knob + " " + pipeline::get_config_field(config, knob));
  }
  v.description = fmt::format("{} with {} on {} ({}), {}x{}{}{}", o.scene.label(), config.technique,
                              device.name, device.gpu, config.width, config.height,
                              knobs.empty() ? "" : ", ", fmt::join(knobs, ", "));

  fmt::print("skinsim validate: {} against the model of {}\n", o.measured, v.description);
  fmt::print("{}", driver::format_validation(v));
  if (!o.json.empty()) {
    io::write_file_atomically(
        o.json,
        driver::to_json(v).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    fmt::print("wrote {}\n", o.json);
  }
  return v.outside() > 0 ? 1 : 0;
}

}  // namespace

Command add_validate_command(CLI::App& app) {
  auto options = std::make_shared<ValidateCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "validate",
      "Compare per-pass GPU times measured on a device (a CSV of pass,ms) with the modelled "
      "frame of the same configuration: exit 0 when every time is inside its modelled range, "
      "1 when one is outside, 2 on bad input");
  cmd->add_option("measured", options->measured,
                  "CSV of measured times: 'pass,ms' lines, '#' comments, optional 'frame,MS' "
                  "(docs/validation.md)")
      ->required();
  add_device_options(*cmd, options->device);
  add_scene_options(*cmd, options->scene);
  add_pipeline_options(*cmd, options->config);
  cmd->add_option("--json", options->json, "Also write the comparison as JSON to this file");
  cmd->add_flag("--allow-unknown-passes", options->allow_unknown_passes,
                "List measured names that are not passes of the modelled frame as not modelled "
                "instead of failing");
  return [options] { return validate(*options); };
}

}  // namespace skinsim::app
