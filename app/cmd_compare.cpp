// `skinsim compare A B`: two runs or two sweeps side by side: what changed in the
// configuration, which counters, times and quality values moved beyond their tolerances, and
// whether the frames differ visibly. Exit 0 the same, 1 different, 2 bad input.
// See docs/reports.md.
#include <fmt/format.h>

#include <filesystem>

#include "app/cli_options.h"
#include "app/commands.h"
#include "driver/run_compare.h"
#include "io/atomic_file.h"
#include "io/run_directory.h"
#include "reports/compare_page.h"
#include "reports/compare_table.h"

namespace skinsim::app {

namespace {

namespace fs = std::filesystem;

struct CompareOptions {
  std::string a;
  std::string b;
  std::string out;  // none: the terminal table only
  double rel_tol = reports::Tolerances{}.modelled;
  double counter_tol = reports::Tolerances{}.counter;
};

// --out is replaced whole, so it must not hold A or B.
void check_out_holds_neither(const std::string& out, const std::string& a, const std::string& b) {
  const fs::path target = fs::weakly_canonical(out);
  for (const std::string& input : {a, b}) {
    const fs::path relative = fs::weakly_canonical(input).lexically_relative(target);
    if (!relative.empty() && *relative.begin() != "..") {
      throw io::OutputError(fmt::format(
          "--out {} would replace {}, an input of the comparison: choose another directory", out,
          input));
    }
  }
}

int compare(const CompareOptions& o) {
  reports::Tolerances tolerances;
  tolerances.counter = o.counter_tol;
  tolerances.modelled = tolerances.quality = o.rel_tol;
  if (o.out.empty()) {
    const reports::Comparison c = driver::compare_outputs(o.a, o.b, tolerances, {});
    fmt::print("{}", reports::format_comparison(c));
    return c.different() ? 1 : 0;
  }
  check_out_holds_neither(o.out, o.a, o.b);
  io::RunDirectory out(o.out, "compare");
  const reports::Comparison c = driver::compare_outputs(o.a, o.b, tolerances, out.staging());
  reports::write_compare_files(c, out.staging());
  out.commit();
  fmt::print("{}wrote {}/compare.html and compare.json\n", reports::format_comparison(c), o.out);
  return c.different() ? 1 : 0;
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Compare two runs or two sweeps: exit 0 when the same within tolerances, 1 when "
      "different, 2 on bad input");
  cmd->add_option("a", options->a, "Run directory (result.json) or sweep directory (results.json)")
      ->required();
  cmd->add_option("b", options->b, "The run or sweep directory to compare with A")->required();
  cmd->add_option("--out", options->out,
                  "Also write compare.html, compare.json, crops and difference images here");
  cmd->add_option("--rel-tol", options->rel_tol,
                  "Relative tolerance of modelled times, bytes and quality metrics")
      ->check(non_negative_real(1e6))
      ->capture_default_str();
  cmd->add_option("--counter-tol", options->counter_tol,
                  "Relative tolerance of emulator counters (0: exact; the emulator is "
                  "deterministic)")
      ->check(non_negative_real(1e6))
      ->capture_default_str();
  return [options] { return compare(*options); };
}

}  // namespace skinsim::app
