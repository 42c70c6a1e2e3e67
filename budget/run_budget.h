// Measuring one budget: its device profile, scene and pipeline configuration rendered on the
// emulated GPU and timed by the cost model; the reference only when a limit needs quality.
#pragma once

#include <string>

#include "budget/budget_file.h"
#include "budget/metrics.h"
#include "gpu_model/device_profile.h"

namespace skinsim::budget {

struct BudgetRun {
  Measurement measurement;
  std::string device;       // profile name
  std::string device_hash;  // fingerprint of the profile file
};

// The budget's device profile; throws BudgetError naming `file` and the budget's line when
// it cannot be found or is invalid.
gpu_model::DeviceProfile load_budget_device(const std::string& file, const Budget& budget,
                                            const std::string& data_dir);

// Renders and measures the budget's frame with `threads` host threads (results identical for
// any count). `with_quality` also renders the reference and adds the quality metrics.
// Throws BudgetError naming `file` and the budget's line on a bad device or scene.
BudgetRun run_budget(const std::string& file, const Budget& budget, const std::string& data_dir,
                     int threads, bool with_quality);

}  // namespace skinsim::budget
