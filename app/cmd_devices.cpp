// `skinsim devices`: the shipped device profiles and their key figures. A broken profile does
// not hide the others: every good one is listed, each broken one gets a line on stderr naming
// the file and the problem, and the exit status is then 2.
#include <fmt/format.h>

#include <cstdio>
#include <memory>

#include "app/cli_options.h"
#include "app/commands.h"
#include "gpu_model/profile_loader.h"
#include "gpu_model/timing_json.h"
#include "gpu_model/timing_table.h"

namespace skinsim::app {

Command add_devices_command(CLI::App& app) {
  auto data_dir = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "devices",
      "List the shipped device profiles (exit 2 after the list if any profile is broken)");
  cmd->add_option("--data-dir", *data_dir, "Directory holding devices/*.toml");
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json, "Print the profiles' key figures as JSON");
  return [data_dir, json] {
    const gpu_model::DeviceCatalog catalog =
        gpu_model::load_device_catalog(data_dir->empty() ? default_data_dir() : *data_dir);
    if (*json) {
      nlohmann::json out = nlohmann::json::array();
      for (const gpu_model::DeviceProfile& p : catalog.profiles) {
        out.push_back(gpu_model::device_json(p));
      }
      fmt::print("{}\n", out.dump(2));
    } else {
      fmt::print("{}\n{}", gpu_model::format_device_table(catalog.profiles),
                 gpu_model::device_table_legend());
    }
    std::fflush(stdout);
    for (const std::string& problem : catalog.problems) {
      fmt::print(stderr, "skinsim devices: error: {}\n", problem);
    }
    return catalog.problems.empty() ? 0 : 2;
  };
}

}  // namespace skinsim::app
