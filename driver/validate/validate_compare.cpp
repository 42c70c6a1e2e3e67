#include "driver/validate/validate_compare.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "gpu_model/frame_cost.h"
#include "results/pass_rows.h"
#include "util/check.h"

namespace skinsim::driver {
namespace {

// Every pass's exposed_ms, then dram_wait_ms (always, so that corners line up with the base).
std::vector<double> row_values(const gpu_model::FrameTiming& t) {
  std::vector<double> values;
  values.reserve(t.schedule.size() + 1);
  for (const gpu_model::PassSlot& s : t.schedule) values.push_back(s.exposed_ms);
  values.push_back(t.dram_wait_ms);
  return values;
}

struct FigureEnds {
  const gpu_model::FigureSpec* spec;
  std::vector<double> at_min;  // row values with the figure at its min
  std::vector<double> at_max;
};

std::string ms3(double ms) {
  return fmt::format("{:.3f}", ms);
}

// A signed difference with `decimals` digits; one that rounds to zero prints as +0, not -0.
std::string signed_fixed(double value, int decimals) {
  std::string text = fmt::format("{:+.{}f}", value, decimals);
  if (text.find_first_not_of("+-0.") == std::string::npos) text[0] = '+';
  return text;
}

nlohmann::json optional_json(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json row_json(const ValidationRow& r) {
  nlohmann::json j = {
      {"name", r.name},
      {"line", r.line > 0 ? nlohmann::json(r.line) : nlohmann::json(nullptr)},
      {"bottleneck", r.bottleneck.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.bottleneck)},
      {"model_ms", r.model ? nlohmann::json(r.model->base) : nlohmann::json()},
      {"model_low_ms", r.model ? nlohmann::json(r.model->low) : nlohmann::json()},
      {"model_high_ms", r.model ? nlohmann::json(r.model->high) : nlohmann::json()},
      {"measured_ms", optional_json(r.measured_ms)}};
  j["error_ms"] = r.compared() ? nlohmann::json(r.error_ms()) : nlohmann::json();
  j["error_percent"] = r.compared() ? optional_json(r.error_percent()) : nlohmann::json();
  j["inside_range"] = r.compared() ? nlohmann::json(r.inside()) : nlohmann::json();
  return j;
}

}  // namespace

std::vector<ModelledMs> row_ms_ranges(const std::vector<sim::PassCounters>& passes,
                                      const gpu_model::DeviceProfile& profile) {
  const gpu_model::FrameTiming base_timing = gpu_model::estimate_frame(passes, profile);
  const std::vector<double> base = row_values(base_timing);
  std::vector<FigureEnds> ends;
  for (const gpu_model::FigureSpec& spec : gpu_model::figure_specs()) {
    const gpu_model::Figure& f = profile.*spec.member;
    if (!f.has_range || spec.affects_counters) continue;
    const auto at = [&](double value) {
      if (value == f.value) return base;  // the base frame: no estimate
      gpu_model::DeviceProfile varied = profile;
      (varied.*spec.member).value = value;
      return row_values(gpu_model::estimate_frame(passes, varied));
    };
    ends.push_back({&spec, at(f.min), at(f.max)});
  }
  const std::size_t count = base_timing.passes.size() + (base_timing.dram_wait_ms > 0.0 ? 1 : 0);
  std::vector<ModelledMs> rows;
  for (std::size_t i = 0; i < count; ++i) {
    // The dram_wait row is the last of row_values.
    const std::size_t k = i < base_timing.passes.size() ? i : base.size() - 1;
    gpu_model::DeviceProfile fastest = profile;
    gpu_model::DeviceProfile slowest = profile;
    for (const FigureEnds& e : ends) {
      const gpu_model::Figure& f = profile.*e.spec->member;
      const bool min_is_faster = e.at_min[k] <= e.at_max[k];
      (fastest.*e.spec->member).value = min_is_faster ? f.min : f.max;
      (slowest.*e.spec->member).value = min_is_faster ? f.max : f.min;
    }
    ModelledMs m;
    m.base = base[k];
    m.low = std::min(m.base, row_values(gpu_model::estimate_frame(passes, fastest))[k]);
    m.high = std::max(m.base, row_values(gpu_model::estimate_frame(passes, slowest))[k]);
    rows.push_back(m);
  }
  return rows;
}

std::optional<double> ValidationRow::error_percent() const {
  SKINSIM_CHECK(compared());
  if (model->base <= 0.0) return std::nullopt;
  return 100.0 * (*measured_ms - model->base) / model->base;
}

bool ValidationRow::inside() const {
  SKINSIM_CHECK(compared());
  return *measured_ms >= model->low - kInsideToleranceMs &&
         *measured_ms <= model->high + kInsideToleranceMs;
}

int Validation::compared() const {
  const auto n =
      std::count_if(rows.begin(), rows.end(), [](const ValidationRow& r) { return r.compared(); });
  return static_cast<int>(n) + (frame.compared() ? 1 : 0);
}

int Validation::outside() const {
  const auto n = std::count_if(rows.begin(), rows.end(),
                               [](const ValidationRow& r) { return r.compared() && !r.inside(); });
  return static_cast<int>(n) + (frame.compared() && !frame.inside() ? 1 : 0);
}

Validation compare_measurements(const Measurements& measured, const gpu_model::FrameTiming& timing,
                                const std::vector<ModelledMs>& rows,
                                const gpu_model::FrameMsRange& frame_range,
                                const ValidateOptions& options) {
  const std::size_t pass_count = timing.passes.size();
  SKINSIM_CHECK(rows.size() == pass_count + (timing.dram_wait_ms > 0.0 ? 1 : 0));
  Validation v;
  v.file = measured.file;
  v.device = timing.device;
  v.range_figures = frame_range.figures;
  v.range_left_out = frame_range.left_out;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ValidationRow row;
    row.name = i < pass_count ? timing.passes[i].name : results::kDramWaitRow;
    row.bottleneck =
        i < pass_count ? gpu_model::unit_name(timing.passes[i].bottleneck) : "bandwidth";
    row.model = rows[i];
    names.push_back(row.name);
    v.rows.push_back(std::move(row));
  }
  bool every_pass_measured = true;
  for (std::size_t i = 0; i < v.rows.size(); ++i) {
    ValidationRow& row = v.rows[i];
    const auto it = std::find_if(measured.passes.begin(), measured.passes.end(),
                                 [&](const MeasuredTime& t) { return t.name == row.name; });
    if (it == measured.passes.end()) {
      v.not_measured.push_back(row.name);
      if (i < pass_count) every_pass_measured = false;
      continue;
    }
    row.measured_ms = it->ms;
    row.line = it->line;
  }
  for (const MeasuredTime& t : measured.passes) {
    if (std::find(names.begin(), names.end(), t.name) != names.end()) continue;
    if (!options.allow_unknown_passes) {
      throw MeasurementError(fmt::format(
          "{}:{}: field 'pass': '{}' is not a pass of the modelled frame (its passes: {}); name "
          "passes as `skinsim run` lists them, or pass --allow-unknown-passes to list it as "
          "not modelled",
          measured.file, t.line, t.name, fmt::join(names, ", ")));
    }
    ValidationRow row;
    row.name = t.name;
    row.measured_ms = t.ms;
    row.line = t.line;
    v.not_modelled.push_back(t.name);
    v.rows.push_back(std::move(row));
  }
  v.frame.name = std::string(kFrameRow);
  v.frame.bottleneck = timing.dram_wait_ms > 0.0 ? "bandwidth" : "pipeline";
  v.frame.model = ModelledMs{timing.frame_ms, frame_range.low, frame_range.high};
  if (measured.frame) {
    v.frame.measured_ms = measured.frame->ms;
    v.frame.line = measured.frame->line;
  } else if (every_pass_measured && v.not_modelled.empty()) {
    double sum = 0.0;
    for (std::size_t i = 0; i < pass_count; ++i) sum += *v.rows[i].measured_ms;
    v.frame.measured_ms = sum;
    v.frame.measured_sum = true;
  }
  return v;
}

std::string format_validation(const Validation& v) {
  std::string out =
      fmt::format("{:<24} {:>9} {:>19} {:>11} {:>9} {:>8} {:>8} {:>10}\n", "pass", "model ms",
                  "model range ms", "measured ms", "error ms", "error %", "in range", "bottleneck");
  const auto line = [&](const ValidationRow& r) {
    const std::string model = r.model ? ms3(r.model->base) : "-";
    const std::string range =
        r.model ? fmt::format("{} - {}", ms3(r.model->low), ms3(r.model->high)) : "not modelled";
    std::string measured = r.measured_ms ? ms3(*r.measured_ms) : "-";
    if (r.measured_sum) measured += "*";
    std::string error_ms = "-";
    std::string error_pct = "-";
    std::string inside = "-";
    if (r.compared()) {
      error_ms = signed_fixed(r.error_ms(), 3);
      const std::optional<double> pct = r.error_percent();
      error_pct = pct ? signed_fixed(*pct, 1) : "n/a";
      inside = r.inside() ? "yes" : "NO";
    } else if (r.model && !r.measured_ms) {
      inside = "unmeasured";
    }
    return fmt::format("{:<24} {:>9} {:>19} {:>11} {:>9} {:>8} {:>8} {:>10}\n", r.name, model,
                       range, measured, error_ms, error_pct, inside,
                       r.bottleneck.empty() ? "-" : r.bottleneck);
  };
  for (const ValidationRow& r : v.rows) out += line(r);
  out += line(v.frame);
  if (v.frame.measured_sum) {
    out += "  * the frame's measured time is the sum of the measured passes (no 'frame' row)\n";
  } else if (!v.frame.measured_ms) {
    out += fmt::format(
        "  the frame is not compared: {} has no 'frame' row and not every pass is measured\n",
        v.file);
  }
  if (!v.not_measured.empty()) {
    out += fmt::format("not measured (in the model, no line in {}): {}\n", v.file,
                       fmt::join(v.not_measured, ", "));
  }
  if (!v.not_modelled.empty()) {
    std::vector<std::string> named;
    for (const ValidationRow& r : v.rows) {
      if (!r.model) named.push_back(fmt::format("{} (line {})", r.name, r.line));
    }
    out += fmt::format("not in the model (measured in {}, not a pass of this frame): {}\n", v.file,
                       fmt::join(named, ", "));
  }
  std::string frame_verdict;
  if (v.frame.compared()) {
    const std::optional<double> pct = v.frame.error_percent();
    frame_verdict =
        fmt::format("; the frame is {} its range, measured - model {} ms{}",
                    v.frame.inside() ? "inside" : "OUTSIDE", signed_fixed(v.frame.error_ms(), 3),
                    pct ? fmt::format(" ({}%)", signed_fixed(*pct, 1)) : "");
  }
  out += fmt::format("{} of {} compared rows inside the modelled range{}\n",
                     v.compared() - v.outside(), v.compared(), frame_verdict);
  out += fmt::format(
      "columns: model ms = the pass's share of the frame (as in `skinsim run`); model range = "
      "that ms over the profile's {} uncertain figures together{}\n"
      "  error = measured - model; in range = measured within the range (+-{} ms); the profile "
      "is never changed (docs/validation.md)\n",
      v.range_figures,
      v.range_left_out
          ? fmt::format(" ({} that change what the emulator counts left out)", v.range_left_out)
          : "",
      kInsideToleranceMs);
  return out;
}

nlohmann::json to_json(const Validation& v) {
  nlohmann::json rows = nlohmann::json::array();
  for (const ValidationRow& r : v.rows) rows.push_back(row_json(r));
  nlohmann::json frame = row_json(v.frame);
  frame["measured_from"] = v.frame.measured_sum  ? nlohmann::json("sum of the measured passes")
                           : v.frame.measured_ms ? nlohmann::json("frame row")
                                                 : nlohmann::json(nullptr);
  return {{"file", v.file},
          {"device", v.device},
          {"configuration", v.description},
          {"rows", rows},
          {"frame", frame},
          {"not_measured", v.not_measured},
          {"not_modelled", v.not_modelled},
          {"compared", v.compared()},
          {"outside_range", v.outside()},
          {"range_uncertain_figures", v.range_figures},
          {"range_figures_needing_rerender_left_out", v.range_left_out},
          {"inside_tolerance_ms", kInsideToleranceMs}};
}

}  // namespace skinsim::driver
