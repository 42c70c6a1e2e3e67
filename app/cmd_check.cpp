// `skinsim check BUDGETS.toml`: evaluate cost budgets (exit 0 all pass, 1 a limit exceeded,
// 2 bad input), with an optional JUnit XML report; `skinsim baseline BUDGETS.toml`: record
// the baseline that baseline-relative limits compare against. See docs/budgets.md.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "app/cli_options.h"
#include "app/commands.h"
#include "budget/baseline_file.h"
#include "budget/budget_file.h"
#include "budget/check.h"
#include "budget/check_table.h"
#include "budget/error.h"
#include "budget/junit.h"
#include "io/atomic_file.h"
#include "io/temp_files.h"

namespace skinsim::app {

namespace {

struct BudgetOptions {
  std::string budgets;
  std::string baseline;  // overrides the budget file's own
  std::string data_dir;
  int threads = 0;
  std::string junit;    // check only
  bool update = false;  // baseline only
};

void add_common_options(CLI::App& cmd, BudgetOptions& o) {
  cmd.add_option("budgets", o.budgets, "Budget file (TOML, see docs/budgets.md)")->required();
  cmd.add_option("--baseline", o.baseline,
                 "Baseline file (default: the budget file's `baseline`, else "
                 "<budgets>.baseline.json beside it)");
  cmd.add_option("--data-dir", o.data_dir,
                 "Directory holding devices/*.toml (default: $SKINSIM_DATA_DIR or the source "
                 "tree's data/)");
  cmd.add_option("--threads", o.threads,
                 "Host worker threads; 0 = all cores (results are identical for any count)")
      ->check(integer_in(0, 256))
      ->capture_default_str();
}

budget::BudgetFile load(const BudgetOptions& o) {
  budget::BudgetFile file = budget::load_budget_file(o.budgets);
  if (!o.baseline.empty()) file.baseline_path = o.baseline;
  return file;
}

std::string data_dir(const BudgetOptions& o) {
  return o.data_dir.empty() ? default_data_dir() : o.data_dir;
}

int check(const BudgetOptions& o) {
  const budget::BudgetFile file = load(o);
  if (!o.junit.empty()) {
    io::require_not_input(o.junit, "--junit", file.path, "the budget file");
    io::require_not_input(o.junit, "--junit", file.baseline_path, "the baseline");
  }
  const bool needs_baseline =
      std::any_of(file.budgets.begin(), file.budgets.end(),
                  [](const budget::Budget& b) { return b.needs_baseline(); });
  // A baseline is required by relative limits; otherwise, when present, it still lets failure
  // messages say how far a metric moved.
  std::optional<budget::Baseline> baseline;
  if (needs_baseline || std::filesystem::exists(file.baseline_path)) {
    baseline = budget::load_baseline(file.baseline_path);
  }
  const budget::CheckReport report = budget::check_budgets(file, baseline, data_dir(o), o.threads);
  for (const std::string& w : report.warnings) {
    fmt::print(stderr, "skinsim check: warning: {} ({})\n", w, file.baseline_path.string());
  }
  fmt::print("{}", budget::format_check_table(report));
  if (!o.junit.empty()) {
    io::remove_stale_temporaries(std::filesystem::path(o.junit).parent_path());
    io::write_file_atomically(o.junit, budget::junit_xml(report, file.path.string()));
    fmt::print("wrote {}\n", o.junit);
  }
  return report.passed() ? 0 : 1;
}

int record(const BudgetOptions& o) {
  const budget::BudgetFile file = load(o);
  io::require_not_input(file.baseline_path, "--baseline", file.path, "the budget file");
  if (std::filesystem::exists(file.baseline_path) && !o.update) {
    throw budget::BudgetError(fmt::format(
        "{}: a baseline already exists; pass --update to replace it", file.baseline_path.string()));
  }
  const budget::Baseline baseline = budget::record_baseline(file, data_dir(o), o.threads);
  io::remove_stale_temporaries(file.baseline_path.parent_path());
  budget::save_baseline(baseline, file.baseline_path);
  fmt::print("recorded the baseline of {} budgets with skinsim {} in {}\n", baseline.budgets.size(),
             baseline.skinsim_version, file.baseline_path.string());
  return 0;
}

}  // namespace

Command add_check_command(CLI::App& app) {
  auto options = std::make_shared<BudgetOptions>();
  CLI::App* cmd = app.add_subcommand(
      "check",
      "Check cost budgets: exit 0 when every limit holds, 1 when one is exceeded, 2 on "
      "bad input");
  add_common_options(*cmd, *options);
  cmd->add_option("--junit", options->junit, "Also write a JUnit XML report (one test per limit)");
  return [options] { return check(*options); };
}

Command add_baseline_command(CLI::App& app) {
  auto options = std::make_shared<BudgetOptions>();
  CLI::App* cmd = app.add_subcommand(
      "baseline",
      "Measure every budget of a file and record the baseline its relative limits "
      "compare against");
  add_common_options(*cmd, *options);
  cmd->add_flag("--update", options->update, "Replace an existing baseline file");
  return [options] { return record(*options); };
}

}  // namespace skinsim::app
