// Runs a sweep into a directory: one reference per (scene, resolution), configurations in
// parallel, each written atomically to configs/<id>.json (+ frame and FLIP error-map PNGs) as it
// finishes. Re-running the same sweep into the same directory skips the configurations whose
// stored fingerprint still matches. A cancellation flag (set from a SIGINT handler by the CLI)
// stops new configurations from starting; the ones in flight finish and are written.
#pragma once

#include <atomic>
#include <cstdio>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "driver/sweep_spec.h"

namespace skinsim::driver {

struct SweepRunOptions {
  std::string out_dir;
  std::string data_dir;  // where device profiles are looked up (gpu_model::load_device_profile)
  int threads = 0;       // host threads (0 = all cores); results do not depend on it
  const std::atomic<bool>* cancel = nullptr;  // set: start no further configuration
  std::FILE* progress = stderr;               // null: silent
  // Called (from a worker thread, one call at a time) after each configuration is written.
  std::function<void(const std::string& id)> on_finished;
};

// A configuration that ran but could not be measured (an error, or a figure that is not a
// number); it has no row, and a later run tries it again.
struct FailedConfig {
  std::string id;
  std::string reason;
};

struct SweepRunSummary {
  int total = 0;
  int resumed = 0;                    // already finished by an earlier run, skipped
  std::vector<std::string> computed;  // ids computed by this run, in finishing order
  int not_run = 0;                    // left unstarted because of cancellation
  std::vector<FailedConfig> failed;   // in expansion order
  int references_rendered = 0;        // references rendered (not loaded from refs/)
  bool cancelled = false;
  double seconds = 0.0;  // wall time
  // Per configuration id, the fingerprint (config_fingerprint) a stored result must have to
  // be this sweep's: assemble_sweep_table shows only those.
  std::map<std::string, nlohmann::json> fingerprints;
  // Stored results in the directory under this sweep's ids but from a different sweep (another
  // --set knob, scene or device) that this run did not replace: ignored, not shown.
  int foreign_ignored = 0;
  // Said once per reference, e.g. that it shows no skin (no skin metrics, and why).
  std::vector<std::string> warnings;
};

// configs/<id>.json and the images, relative to the sweep directory.
std::string config_json_path(const std::string& id);
std::string config_frame_path(const std::string& id);
std::string config_error_path(const std::string& id);

// Runs `configs` (from expand_sweep(spec)). Throws SweepError / the modules' errors on bad
// input (an unknown device, an unreadable scene) before any configuration is written.
SweepRunSummary run_sweep(const SweepSpec& spec, const std::vector<SweepConfig>& configs,
                          const SweepRunOptions& options);

}  // namespace skinsim::driver
