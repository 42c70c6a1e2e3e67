#include "budget/check.h"

#include <chrono>

#include "budget/definition_fingerprint.h"
#include "budget/device_fingerprint.h"
#include "budget/run_budget.h"

namespace skinsim::budget {

int CheckReport::limit_count() const {
  int n = 0;
  for (const BudgetOutcome& b : budgets) n += static_cast<int>(b.limits.size());
  return n;
}

int CheckReport::failure_count() const {
  int n = 0;
  for (const BudgetOutcome& b : budgets) {
    for (const LimitResult& r : b.limits) n += r.passed ? 0 : 1;
  }
  return n;
}

CheckReport check_budgets(const BudgetFile& file, const std::optional<Baseline>& baseline,
                          const std::string& data_dir, int threads) {
  const std::string path = file.path.string();
  CheckReport report;
  if (baseline) {
    if (auto w = version_warning(*baseline, skinsim_version())) report.warnings.push_back(*w);
  }
  for (const Budget& budget : file.budgets) {
    const auto start = std::chrono::steady_clock::now();
    // Quality metrics need the reference frame: render it only when a limit uses one.
    const BudgetRun run = run_budget(path, budget, data_dir, threads, budget.needs_quality());
    const BaselineEntry* entry = nullptr;
    if (baseline) {
      const auto it = baseline->budgets.find(budget.name);
      if (it != baseline->budgets.end()) entry = &it->second;
      if (auto w = device_warning(*baseline, budget.name, run.device, run.device_hash)) {
        report.warnings.push_back(*w);
      }
      if (auto w = definition_warning(*baseline, budget.name,
                                      definition_fingerprint(budget, file.path), path)) {
        report.warnings.push_back(*w);
      }
    }
    BudgetOutcome outcome;
    outcome.name = budget.name;
    outcome.device = run.device;
    outcome.limits = evaluate_budget(path, budget, run.measurement, entry);
    outcome.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    report.budgets.push_back(std::move(outcome));
  }
  return report;
}

Baseline record_baseline(const BudgetFile& file, const std::string& data_dir, int threads) {
  Baseline baseline;
  baseline.skinsim_version = skinsim_version();
  for (const Budget& budget : file.budgets) {
    // Every metric is recorded, quality included, so a limit added later finds its value.
    const BudgetRun run = run_budget(file.path.string(), budget, data_dir, threads, true);
    BaselineEntry entry{run.device, run.device_hash, definition_fingerprint(budget, file.path),
                        run.measurement.metrics};
    // Refuse to record a baseline the budget's own limits could not be checked against (a
    // limit on a pass the frame does not have).
    evaluate_budget(file.path.string(), budget, run.measurement, &entry);
    baseline.budgets[budget.name] = std::move(entry);
  }
  return baseline;
}

}  // namespace skinsim::budget
