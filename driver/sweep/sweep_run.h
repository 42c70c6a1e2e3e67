// Runs a sweep into a directory: one reference per (scene, resolution), then the configurations
// one at a time, each frame on every host thread, each written atomically to configs/<id>.json
// (+ frame and FLIP error-map PNGs) as it finishes. Re-running the same sweep into the same
// directory skips the configurations whose stored fingerprint still matches. A cancellation
// flag (set from a SIGINT handler by the CLI) stops new configurations from starting; the one
// running finishes and is written.
// With a shard (driver/sweep/sweep_shard.h) it computes only that part of the sweep, and several
// processes may run different shards into one directory at once.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "driver/frame/reference_store.h"
#include "driver/sequence/sequence.h"
#include "driver/sweep/sweep_shard.h"
#include "driver/sweep/sweep_spec.h"

namespace skinsim::driver {

struct SweepRunOptions {
  std::string out_dir;
  std::string data_dir;  // where device profiles are looked up (gpu_model::load_device_profile)
  int threads = 0;       // host threads (0 = all cores); results do not depend on it
  const std::atomic<bool>* cancel = nullptr;  // set: start no further configuration
  std::FILE* progress = stderr;               // null: silent
  std::optional<SweepShard> shard;            // set: compute only this shard's configurations
  bool compute = true;                        // false: compute nothing, only take stock (a merge)
  // Where references are shared with other runs and sweeps (reference_store.h); none: each
  // is rendered unless refs/ has it.
  std::optional<ReferenceStore> reference_store;
  // Called (from a worker thread, one call at a time) after each configuration is written.
  std::function<void(const std::string& id)> on_finished;
  // Set: each configuration plays this sequence (driver/sequence/sequence_sweep.h).
  const Sequence* sequence = nullptr;
};

// A configuration that ran but could not be measured (an error, or a figure that is not a
// number); it has no row, and a later run tries it again.
struct FailedConfig {
  std::string id;
  std::string reason;
};

// A configuration without a result; `reason` says which shard left it and why, or is empty
// when no shard process has written to the directory.
struct MissingConfig {
  std::string id;
  std::string reason;
};

struct SweepRunSummary {
  int total = 0;      // configurations of the whole sweep
  int this_part = 0;  // of them, those this run is responsible for (its shard's, or all)
  int resumed = 0;    // of this part, already finished by an earlier run, skipped
  std::vector<std::string> computed;  // ids computed by this run, in finishing order
  int not_run = 0;                    // left unstarted because of cancellation
  std::vector<FailedConfig> failed;   // in expansion order
  // This part's configurations without a result when the run started, with the reason the
  // shard statuses give, listed when computing nothing (a merge: they stay missing) or when
  // shards have written to the directory (this run computes what they left).
  std::vector<MissingConfig> left_by_shards;
  int references_rendered = 0;    // references rendered (not loaded from refs/ or the store)
  int references_from_store = 0;  // references taken from SweepRunOptions::reference_store
  // Render passes of the computed configurations: replayed from an identical pass of an
  // earlier configuration (sim/pass_memo.h), and rendered.
  int passes_replayed = 0;
  int passes_rendered = 0;
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
