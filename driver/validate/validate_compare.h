// `skinsim validate` without the CLI: a modelled frame against a user's measured per-pass
// times (validate_measurements.h). It reads the model; it never changes a profile.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "driver/validate/validate_measurements.h"
#include "gpu_model/device_profile.h"
#include "gpu_model/sensitivity.h"
#include "gpu_model/timing.h"
#include "sim/counters.h"

namespace skinsim::driver {

// A modelled time with the range it spans over the profile's uncertain figures.
struct ModelledMs {
  double base = 0.0;
  double low = 0.0;
  double high = 0.0;
};

// Each row's ms (the passes' exposed_ms, then dram_wait when the frame is bandwidth-bound,
// as gpu_model::format_frame_table lists them) over the profile's uncertain figures, the way
// gpu_model::frame_ms_range does it for the frame, one row at a time: for each figure with a
// range (figures that change the emulator's counters left out) the end that lowers, or
// raises, the row's ms is picked from its one-at-a-time estimate, then all are set at once.
// low <= base <= high.
std::vector<ModelledMs> row_ms_ranges(const std::vector<sim::PassCounters>& passes,
                                      const gpu_model::DeviceProfile& profile);

// Half the last digit of the printed milliseconds: a measurement this close outside a range
// is counted inside (a CSV copied from the table must not fall outside by rounding).
inline constexpr double kInsideToleranceMs = 0.0005;

// One row of the comparison: a pass, dram_wait, or the frame.
struct ValidationRow {
  std::string name;
  std::string bottleneck;           // the model's, empty when the model has no such row
  std::optional<ModelledMs> model;  // empty: measured but not in the model
  std::optional<double> measured_ms;
  int line = 0;               // the measurement's line in the file (0: none)
  bool measured_sum = false;  // frame only: the sum of the measured passes, no `frame` row

  bool compared() const { return model && measured_ms; }
  double error_ms() const { return *measured_ms - model->base; }  // measured - model
  // 100 x (measured - model) / model; empty when the model's time is 0.
  std::optional<double> error_percent() const;
  bool inside() const;  // low - tolerance <= measured <= high + tolerance
};

struct Validation {
  std::string file;
  std::string device;
  std::string description;          // what was modelled: technique, resolution, knobs
  std::vector<ValidationRow> rows;  // the model's rows in frame order, then unknown measured
  ValidationRow frame;
  std::vector<std::string> not_measured;  // model rows without a measurement
  std::vector<std::string> not_modelled;  // measured names the model does not have
  int range_figures = 0;                  // uncertain figures the ranges include
  int range_left_out = 0;                 // and those left out (they need a re-render)

  int compared() const;
  int outside() const;  // compared rows (frame included) outside their range
};

struct ValidateOptions {
  // Measured names that are not passes of the modelled frame are listed in not_modelled
  // instead of failing.
  bool allow_unknown_passes = false;
};

// Matches the measurements to the modelled frame. Throws MeasurementError naming the file,
// line and field for a measured name that is not a pass of the frame (unless
// allow_unknown_passes), listing the frame's passes. The frame's measured time is the `frame`
// row, else the sum of the measured passes when every pass is measured.
Validation compare_measurements(const Measurements& measured, const gpu_model::FrameTiming& timing,
                                const std::vector<ModelledMs>& rows,
                                const gpu_model::FrameMsRange& frame_range,
                                const ValidateOptions& options = {});

// The terminal table: per row model ms, its range, measured ms, error ms and %, in range; then
// what was not measured or not modelled, and a one-line verdict.
std::string format_validation(const Validation& v);

// validation.json: the same, one object per row.
nlohmann::json to_json(const Validation& v);

}  // namespace skinsim::driver
