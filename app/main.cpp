// skinsim: emulate a mobile tile-based GPU running skin-rendering pipelines, and model what
// each costs on a device.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <exception>
#include <map>

#include "app/commands.h"
#include "driver/host_memory.h"

int main(int argc, char** argv) {
  skinsim::driver::retain_freed_memory();
  CLI::App app{
      "skinsim: emulate a tile-based mobile GPU (PowerVR SGX-class) running skin-rendering "
      "pipelines, and model their cost per device"};
  app.require_subcommand(1);
  std::map<const CLI::App*, skinsim::app::Command> commands;
  auto add = [&](skinsim::app::Command c) { commands[app.get_subcommands({}).back()] = std::move(c); };
  add(skinsim::app::add_run_command(app));
  add(skinsim::app::add_devices_command(app));
  add(skinsim::app::add_shaders_command(app));
  add(skinsim::app::add_sweep_command(app));
  add(skinsim::app::add_microbench_command(app));
  add(skinsim::app::add_check_command(app));
  add(skinsim::app::add_baseline_command(app));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints the message
    return 2;
  } catch (const std::exception& e) {  // a knob's own validation (pipeline::ConfigError)
    fmt::print(stderr, "skinsim: error: {}\n", e.what());
    return 2;
  }
  for (const auto& [sub, run] : commands) {
    if (!sub->parsed()) continue;
    try {
      return run();
    } catch (const std::exception& e) {
      fmt::print(stderr, "skinsim {}: error: {}\n", sub->get_name(), e.what());
      return 2;
    }
  }
  return 2;
}
