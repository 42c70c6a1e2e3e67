// skinsim: emulate a mobile tile-based GPU running skin-rendering pipelines, and model what
// each costs on a device.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <exception>
#include <filesystem>
#include <map>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "app/commands.h"
#include "driver/frame/host_memory.h"
#include "pipeline/knob.h"
#include "util/simd_dispatch.h"
#include "util/user_error.h"

namespace {

// Exit statuses: 0 success, 1 a check failed (budgets), 2 bad input the user can fix,
// 3 an internal error (a bug in skinsim).
constexpr int kExitBadInput = 2;
constexpr int kExitInternalError = 3;

// Runs `body` and maps what escapes it to a message and an exit status. `where` prefixes the
// message ("skinsim" or "skinsim run").
template <typename Body>
int report_errors(const std::string& where, Body&& body) {
  try {
    return body();
  } catch (const skinsim::UserError& e) {
    fmt::print(stderr, "{}: error: {}\n", where, e.what());
    return kExitBadInput;
  } catch (const std::filesystem::filesystem_error& e) {  // names the path at fault
    fmt::print(stderr, "{}: error: {}\n", where, e.what());
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr,
               "{}: error: out of memory: the input asks for more memory than this machine can "
               "give (a smaller resolution, scene or sweep may fit)\n",
               where);
    return kExitBadInput;
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}: internal error (a bug in skinsim, please report it): {}\n", where,
               e.what());
    return kExitInternalError;
  }
}

// Levenshtein distance: how many single-character edits turn `a` into `b`.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
    }
  }
  return row[b.size()];
}

// The message for an option `sub` does not have: the option it most likely meant, found by
// the knob's name (--light_azimuth_deg is knob light_azimuth_deg, option --light-azimuth),
// by '_' for '-', or by a few typos; CLI11 alone says only "arguments were not expected".
std::string unknown_option_message(const CLI::App& sub, std::string_view option) {
  const std::string name(option.substr(2));
  std::string dashed = name;
  std::replace(dashed.begin(), dashed.end(), '_', '-');
  std::string hint;
  for (const skinsim::pipeline::KnobSpec& knob : skinsim::pipeline::all_knobs()) {
    if ((knob.name == name || knob.name == dashed) && sub.get_option_no_throw(knob.flag)) {
      hint = fmt::format("{} (knob {}; or --set {}=VALUE)", knob.flag, knob.name, knob.name);
    }
  }
  if (hint.empty()) {
    std::size_t best = 4;  // more edits than this is no longer a typo
    for (const CLI::Option* o : sub.get_options()) {
      for (const std::string& long_name : o->get_lnames()) {
        const std::size_t d = edit_distance(dashed, long_name);
        if (d < best) best = d, hint = "--" + long_name;
      }
    }
  }
  return fmt::format("{}: unknown option {}{}", sub.get_name(), option,
                     hint.empty() ? fmt::format(" (`skinsim {} --help` lists them)", sub.get_name())
                                  : "; did you mean " + hint + "?");
}

// Checks CLI11 gets wrong before it parses: it hands "--opt=" (an empty value) the next
// argument as its value, reports an unknown subcommand as "A subcommand is required", and an
// unknown option without a hint.
void check_raw_arguments(CLI::App& app, int argc, char** argv) {
  std::vector<std::string> known;
  for (const CLI::App* sub : app.get_subcommands({})) known.push_back(sub->get_name());
  if (argc > 1 && argv[1][0] != '-' &&
      std::find(known.begin(), known.end(), argv[1]) == known.end()) {
    throw skinsim::UserError(
        fmt::format("unknown subcommand '{}' (known: {})", argv[1], fmt::join(known, ", ")));
  }
  const CLI::App* sub = argc > 1 && argv[1][0] != '-' ? app.get_subcommand(argv[1]) : nullptr;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--") break;  // what follows is positional
    if (arg.starts_with("--") && arg.ends_with("=")) {
      throw skinsim::UserError(
          fmt::format("option {} needs a value after '='", arg.substr(0, arg.size() - 1)));
    }
    const std::string_view option = arg.substr(0, arg.find('='));
    if (sub && option.starts_with("--") && option != "--help" &&
        !sub->get_option_no_throw(std::string(option))) {
      throw skinsim::UserError(unknown_option_message(*sub, option));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  skinsim::driver::retain_freed_memory();
  CLI::App app{
      "skinsim: emulate a tile-based mobile GPU (PowerVR SGX-class) running skin-rendering "
      "pipelines, and model their cost per device"};
  app.require_subcommand(1);
  app.footer(
      "Environment:\n"
      "  SKINSIM_CACHE_DIR  where runs and sweeps share rendered references (default\n"
      "                     $XDG_CACHE_HOME/skinsim or ~/.cache/skinsim; 'off' for none)\n"
      "  SKINSIM_SIMD       auto (default: AVX where the processor has it) or sse2");
  std::map<const CLI::App*, skinsim::app::Command> commands;
  auto add = [&](skinsim::app::Command c) {
    commands[app.get_subcommands({}).back()] = std::move(c);
  };
  add(skinsim::app::add_run_command(app));
  add(skinsim::app::add_devices_command(app));
  add(skinsim::app::add_shaders_command(app));
  add(skinsim::app::add_sweep_command(app));
  add(skinsim::app::add_microbench_command(app));
  add(skinsim::app::add_check_command(app));
  add(skinsim::app::add_baseline_command(app));
  add(skinsim::app::add_techniques_command(app));
  add(skinsim::app::add_knobs_command(app));
  add(skinsim::app::add_compare_command(app));
  add(skinsim::app::add_validate_command(app));
  add(skinsim::app::add_export_command(app));
  add(skinsim::app::add_truth_command(app));
  const int parsed = report_errors("skinsim", [&] {  // knobs validate as they are parsed
    skinsim::check_simd_environment();
    check_raw_arguments(app, argc, argv);
    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
      return app.exit(e);
    } catch (const CLI::ParseError& e) {
      app.exit(e);  // prints the message
      return kExitBadInput;
    }
    return -1;
  });
  if (parsed != -1) return parsed;
  for (const auto& [sub, run] : commands) {
    if (sub->parsed()) return report_errors("skinsim " + sub->get_name(), run);
  }
  return kExitBadInput;
}
