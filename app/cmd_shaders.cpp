// `skinsim shaders`: every shader's op profile, like an offline shader compiler's report.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <iostream>

#include "app/commands.h"
#include "driver/frame/result_json.h"
#include "pipeline/shader_catalog.h"
#include "pipeline/technique.h"

namespace skinsim::app {

Command add_shaders_command(CLI::App& app) {
  auto json = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand(
      "shaders", "Print every shader's op profile (ALU ops by class, texture reads by kind)");
  cmd->add_flag("--json", *json, "Print JSON instead of a table");
  return [json] {
    const auto catalog = pipeline::shader_catalog();
    if (*json) {
      nlohmann::json out = nlohmann::json::array();
      for (const auto& [s, techniques] : catalog) {
        nlohmann::json entry = driver::to_json(s.profile);
        entry["name"] = s.name;
        entry["techniques"] = techniques;
        out.push_back(entry);
      }
      fmt::print("{}\n", out.dump(2));
      return 0;
    }
    // mediump: how many of the ALU ops run at mediump (the skin_precision knob's variants).
    fmt::print("{:<38} {:>6} {:>6} {:>6} {:>7} {:>6} {:>7} {:>6} {:>7}  {}\n", "shader", "vector",
               "scalar", "transc", "mediump", "tex_in", "tex_dep", "inputs", "outputs",
               "techniques");
    for (const auto& [s, techniques] : catalog) {
      const sim::OpProfile& p = s.profile;
      const bool every = techniques.size() == pipeline::all_techniques().size();
      const std::uint32_t mediump =
          p.vector_ops_mediump + p.scalar_ops_mediump + p.transcendental_ops_mediump;
      fmt::print("{:<38} {:>6} {:>6} {:>6} {:>7} {:>6} {:>7} {:>6} {:>7}  {}\n", s.name,
                 p.vector_ops, p.scalar_ops, p.transcendental_ops, mediump,
                 p.texture_reads_independent, p.texture_reads_dependent, p.input_floats,
                 p.output_floats,
                 every ? std::string("all") : fmt::format("{}", fmt::join(techniques, ",")));
    }
    return 0;
  };
}

}  // namespace skinsim::app
