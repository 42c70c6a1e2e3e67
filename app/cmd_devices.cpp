// `skinsim devices`: the shipped device profiles and their key figures.
#include <fmt/format.h>

#include "app/cli_options.h"
#include "app/commands.h"
#include "gpu_model/timing_table.h"

namespace skinsim::app {

Command add_devices_command(CLI::App& app) {
  auto data_dir = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("devices", "List the shipped device profiles");
  cmd->add_option("--data-dir", *data_dir, "Directory holding devices/*.toml");
  return [data_dir] {
    fmt::print("{}", gpu_model::format_device_table(data_dir->empty() ? default_data_dir() : *data_dir));
    return 0;
  };
}

}  // namespace skinsim::app
