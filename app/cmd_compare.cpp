// `skinsim compare A B`: two runs or two sweeps side by side: what changed in the
// configuration, which counters, times and quality values moved beyond their tolerances, and
// whether the frames differ visibly. Exit 0 the same, 1 different, 2 bad input.
// See docs/reports.md.
#include <fmt/format.h>

#include <filesystem>

#include "app/cli_options.h"
#include "app/commands.h"
#include "driver/sweep/run_compare.h"
#include "driver/truth/truth_compare.h"
#include "driver/truth/truth_judge.h"
#include "io/atomic_file.h"
#include "io/json_input.h"
#include "io/read_file.h"
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
  std::string truth;                 // --truth: "cached", a file, or none
  driver::TruthChoice truth_choice;  // --truth-samples, --truth-seed
};

// `--truth`: both frames against the truth, printed after the comparison (and into
// compare.json with --out). Computed first, so a bad truth fails before anything is written.
nlohmann::json judge_with_truth(const CompareOptions& o) {
  driver::require_cached_for_choice(o.truth, o.truth_choice);
  if (o.truth.empty()) return nullptr;
  driver::require_truth("--truth", o.truth);
  return driver::compare_with_truth(o.a, o.b, o.truth, o.truth_choice);
}

void print_truth(const nlohmann::json& truth) {
  if (truth.is_null()) return;
  for (const std::string& line : driver::truth_compare_lines(truth)) fmt::print("{}\n", line);
}

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
  const nlohmann::json truth = judge_with_truth(o);
  if (o.out.empty()) {
    const reports::Comparison c = driver::compare_outputs(o.a, o.b, tolerances, {});
    fmt::print("{}", reports::format_comparison(c));
    print_truth(truth);
    return c.different() ? 1 : 0;
  }
  check_out_holds_neither(o.out, o.a, o.b);
  io::RunDirectory out(o.out, "compare");
  const reports::Comparison c = driver::compare_outputs(o.a, o.b, tolerances, out.staging());
  reports::write_compare_files(c, out.staging());
  if (!truth.is_null()) {
    const std::filesystem::path json = out.staging() / "compare.json";
    nlohmann::json written =
        io::parse_json(io::read_regular_file(json, "compare.json"), "compare.json", json);
    written["truth"] = truth;
    io::write_file_atomically(json.string(), written.dump(2) + "\n");
  }
  out.commit();
  fmt::print("{}", reports::format_comparison(c));
  print_truth(truth);
  fmt::print("wrote {}/compare.html and compare.json\n", o.out);
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
  cmd->add_option(
      "--truth", options->truth,
      "Also judge both runs' frames against a path-traced truth: `cached` (the one "
      "both were judged with by `run --truth cached`) a linear EXR or PNG of the view, "
      "or a `skinsim truth` directory of it (docs/validation.md); the exit status is unchanged");
  add_truth_choice_options(*cmd, options->truth_choice);
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
