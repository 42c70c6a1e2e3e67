// What the sweep says about each knob, in one sentence, computed from its own results.
//
// Per group (ConfigResult::group) and technique, a knob is judged around the technique's
// finest configuration F (its lowest FLIP against the reference, the one every row's
// vs_finest compares with): the rows that differ from F in that knob alone are a clean
// one-knob slice, so their frame times are the knob's cost and their vs_finest the knob's
// visible effect. The technique knob itself is judged on each technique's finest row
// against the group's best (vs_best). Knobs with one value per group (device, resolution,
// the reference's light and framing) define the groups and are not judged.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "results/sweep_table.h"

namespace skinsim::reports {

struct KnobVerdict {
  std::string group;
  std::string technique;  // "" for the technique knob, and in sweeps without one
  std::string knob;
  std::string around;  // id of the configuration the knob is varied around
  enum class Kind {
    one_value,     // the knob has one value for this technique: nothing to compare
    not_isolated,  // no row differs from `around` in this knob alone
    measured,
  } kind = Kind::measured;
  bool time_effect = false;     // the values' frame times span kNoTimeEffect or more
  bool visible_effect = false;  // some value differs visibly from `around`'s
  std::string sentence;
};

// A spread of frame times under this fraction of the frame is reported as no time effect:
// the model's smaller differences are below what a frame-time measurement on a device (its
// frame-to-frame variation) resolves.
inline constexpr double kNoTimeEffect = 0.01;

// Every judged knob, by group, then technique (the technique knob first), then knob name.
// `metric` is the lower-is-better metric the finest rows were picked by (recommend_metric).
std::vector<KnobVerdict> knob_verdicts(const results::SweepTable& table, const std::string& metric);

// What a technique's best knobs leave against the reference (technique error) and what its
// other knob values add on top (knob error: FLIP against the technique's finest row).
struct TechniqueError {
  std::string group;
  std::string technique;         // "" in sweeps without a technique knob
  std::string finest;            // id
  double technique_error = 0.0;  // metric of `finest` against the reference
  int configurations = 0;        // rows of this technique in the group
  std::string worst;             // id of the row with the largest knob error ("" if none)
  double knob_error = 0.0;       // its FLIP mean against `finest`
  double knob_visible_px = 0.0;  // its pixels above the visibility threshold
  int visibly_worse = 0;         // rows whose frame differs visibly from `finest`
  std::string sentence;
};

std::vector<TechniqueError> technique_errors(const results::SweepTable& table,
                                             const std::string& metric);

// Knobs with one value wherever they are used (they are not judged), "name=value" sorted by
// name.
std::vector<std::string> unswept_knobs(const results::SweepTable& table);

// The findings results.json keeps beside the rows: metric, recommendations, knob verdicts
// and technique errors (derived from the rows; read_sweep_json ignores them).
nlohmann::json findings_json(const results::SweepTable& table);

}  // namespace skinsim::reports
