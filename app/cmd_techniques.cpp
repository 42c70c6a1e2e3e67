// `skinsim techniques` and `skinsim knobs`: the technique registry and the knob table as a
// user reads them (a table, JSON, or the Markdown that docs/techniques.md and docs/knobs.md
// hold, so the docs cannot drift from the code: tests compare them).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "pipeline/config.h"
#include "pipeline/technique.h"

namespace skinsim::app {

namespace {

enum class Format { kTable, kJson, kMarkdown };

void add_format_flags(CLI::App& cmd, Format& format) {
  cmd.add_flag_callback(
      "--json", [&format] { format = Format::kJson; }, "Print JSON");
  cmd.add_flag_callback(
      "--markdown", [&format] { format = Format::kMarkdown; },
      "Print the Markdown table the docs hold");
}

// Which techniques use a knob: "all" for the common knobs.
std::string users_of(const pipeline::KnobSpec& knob) {
  for (const pipeline::KnobSpec& common : pipeline::common_knobs()) {
    if (common.name == knob.name) return "all";
  }
  std::vector<std::string> users;
  for (const pipeline::TechniqueSpec* t : pipeline::all_techniques()) {
    for (const pipeline::KnobSpec& own : t->knobs) {
      if (own.name == knob.name) users.push_back(t->name);
    }
  }
  return fmt::format("{}", fmt::join(users, ", "));
}

// The technique's passes in frame order, as run, validate, export and the timeline name them:
// every technique's frame starts with the key light's shadow-map pass while --shadows is on.
std::string frame_passes(const pipeline::TechniqueSpec& t) {
  return "shadow, " + t.passes;
}
constexpr const char* kShadowNote =
    "shadow: the key light's depth-only shadow-map pass, first in every technique's frame "
    "while --shadows is on (the default)";

int print_techniques(Format format) {
  const auto& all = pipeline::all_techniques();
  if (format == Format::kJson) {
    nlohmann::json out = nlohmann::json::array();
    for (const pipeline::TechniqueSpec* t : all) {
      out.push_back({{"name", t->name},
                     {"passes", frame_passes(*t)},
                     {"summary", t->summary},
                     {"knobs", pipeline::technique_knobs(t->name)}});
    }
    fmt::print("{}\n", out.dump(2));
  } else if (format == Format::kMarkdown) {
    fmt::print("| name | passes | what it is | own knobs |\n|---|---|---|---|\n");
    for (const pipeline::TechniqueSpec* t : all) {
      std::vector<std::string> knobs;
      for (const std::string& k : pipeline::technique_knobs(t->name))
        knobs.push_back("`" + k + "`");
      fmt::print("| `{}` | {} | {} | {} |\n", t->name, frame_passes(*t), t->summary,
                 knobs.empty() ? "-" : fmt::format("{}", fmt::join(knobs, ", ")));
    }
    fmt::print("\n{}.\n", kShadowNote);
  } else {
    for (const pipeline::TechniqueSpec* t : all) {
      fmt::print("{:<14} {}\n{:<14} passes: {}\n", t->name, t->summary, "", frame_passes(*t));
      const auto knobs = pipeline::technique_knobs(t->name);
      if (!knobs.empty()) fmt::print("{:<14} knobs: {}\n", "", fmt::join(knobs, ", "));
    }
    fmt::print("\n{}\n", kShadowNote);
  }
  return 0;
}

int print_knobs(Format format) {
  const pipeline::PipelineConfig defaults;
  if (format == Format::kJson) {
    nlohmann::json out = nlohmann::json::array();
    for (const pipeline::KnobSpec& k : pipeline::all_knobs()) {
      nlohmann::json row = {{"name", k.name},
                            {"option", k.flag},
                            {"values", k.values},
                            {"default", k.get(defaults)},
                            {"techniques", users_of(k)},
                            {"help", k.help}};
      if (!k.sweep_flag.empty()) row["sweep_option"] = k.sweep_flag;
      out.push_back(std::move(row));
    }
    fmt::print("{}\n", out.dump(2));
  } else if (format == Format::kMarkdown) {
    fmt::print(
        "| knob | option | values | default | techniques | what |\n"
        "|---|---|---|---|---|---|\n");
    for (const pipeline::KnobSpec& k : pipeline::all_knobs()) {
      fmt::print("| `{}` | `{}` | {} | `{}` | {} | {} |\n", k.name, k.flag, k.values,
                 k.get(defaults), users_of(k), k.help);
    }
  } else {
    for (const pipeline::KnobSpec& k : pipeline::all_knobs()) {
      fmt::print("{:<20} {:<24} {} (default {}; {})\n{:<20} {}\n", k.name, k.flag, k.values,
                 k.get(defaults), users_of(k), "", k.help);
    }
    fmt::print(
        "\nSet a knob with its option, or by its name: --set knob=value (run, sweep, validate, "
        "export).\n");
  }
  return 0;
}

}  // namespace

Command add_techniques_command(CLI::App& app) {
  auto format = std::make_shared<Format>(Format::kTable);
  CLI::App* cmd = app.add_subcommand(
      "techniques", "List the skin techniques: passes, what each is, its own knobs");
  add_format_flags(*cmd, *format);
  return [format] { return print_techniques(*format); };
}

Command add_knobs_command(CLI::App& app) {
  auto format = std::make_shared<Format>(Format::kTable);
  CLI::App* cmd = app.add_subcommand(
      "knobs",
      "List every pipeline knob: option, accepted values, default, which techniques use it");
  add_format_flags(*cmd, *format);
  return [format] { return print_knobs(*format); };
}

}  // namespace skinsim::app
