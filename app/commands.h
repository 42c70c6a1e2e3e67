// The skinsim subcommands. Each registers its options on the CLI and returns the function
// that runs it (exit code: 0 ok, 1 a check failed, 2 bad input).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace skinsim::app {

using Command = std::function<int()>;

Command add_run_command(CLI::App& app);
Command add_devices_command(CLI::App& app);
Command add_shaders_command(CLI::App& app);
Command add_sweep_command(CLI::App& app);
Command add_microbench_command(CLI::App& app);
Command add_check_command(CLI::App& app);
Command add_baseline_command(CLI::App& app);
Command add_techniques_command(CLI::App& app);
Command add_knobs_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_validate_command(CLI::App& app);
Command add_export_command(CLI::App& app);
Command add_truth_command(CLI::App& app);

}  // namespace skinsim::app
