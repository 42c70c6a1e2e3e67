// The results of a sweep over pipeline configurations: the sweep engine fills these structs,
// the reports draw them. results.json (to_json/from_json) holds everything the charts and the
// HTML report need, so both can be regenerated from that file alone.
#pragma once

#include <map>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "results/pass_rows.h"
#include "results/sequence_summary.h"

namespace skinsim::results {

// Modelled cost of one render pass of one configuration. A frame's passes, plus a "dram_wait"
// entry when its DRAM traffic outlasts the pipeline (kDramWaitRow), add up to its
// frame_ms.
struct PassCost {
  std::string name;        // e.g. "irradiance", "blur_h", "blur_v", "skin"
  double ms = 0.0;         // its share of the frame (gpu_model::PassSlot::exposed_ms)
  std::string bottleneck;  // unit that bounds the pass, e.g. "alu", "texture", "bandwidth"
  std::map<std::string, double> dram_bytes_by_cause;  // e.g. "color_store", "texture"
  // Where it sits in the frame's two-stage pipeline, ms from the frame's start: its tiler
  // (TA) stage and its renderer (3D) stage (docs/cost-model.md, "Frame").
  double ta_start_ms = 0.0;
  double ta_end_ms = 0.0;
  double render_start_ms = 0.0;
  double render_end_ms = 0.0;
};

// A fragment program one configuration ran: where, on how many fragments, and its op profile
// (from the shader's own code: ALU ops by class, texture reads by kind).
struct ProgramCost {
  std::string pass;
  std::string program;
  double fragments = 0.0;
  int vector_ops = 0;
  int scalar_ops = 0;
  int transcendental_ops = 0;
  int texture_reads_independent = 0;
  int texture_reads_dependent = 0;
};

// One frame compared with another configuration's frame (both 8-bit, as stored): FLIP over
// the reference's skin (the whole frame when it shows none).
struct FrameComparison {
  std::string against;  // id of the other configuration
  double flip_mean = 0.0;
  double flip_p99 = 0.0;
  double visible_px = 0.0;  // pixels above quality::flip_visibility_threshold()
  bool visible = false;     // they cover at least quality::flip_visible_area_pixels()
};

// One configuration of the sweep and what it cost and bought.
struct ConfigResult {
  std::string id;     // unique within the sweep; used in file names and tables
  std::string label;  // short human-readable name, e.g. "scale 0.5, LUT 32x128"
  // Swept parameters: technique, scale, lut, lut_format, blur_iterations, device, resolution...
  std::map<std::string, std::string> knobs;
  double frame_ms = 0.0;
  // frame_ms with the device profile's uncertain figures all at their fast / slow ends
  // (gpu_model::frame_ms_range; figures that need a re-render are left out).
  double frame_ms_low = 0.0;
  double frame_ms_high = 0.0;
  double fps = 0.0;
  double dram_bytes = 0.0;  // per frame
  // Dynamic energy per frame, mJ (gpu_model::FrameEnergy), and with every energy figure of
  // the device profile at its range minimum / maximum.
  double energy_mj = 0.0;
  double energy_mj_low = 0.0;
  double energy_mj_high = 0.0;
  std::vector<PassCost> passes;
  std::vector<ProgramCost> programs;  // fragment programs with shaded fragments
  // Image quality against the reference: psnr_skin, ssim_skin, flip_skin, psnr_frame, ...
  std::map<std::string, double> quality;
  std::string frame_image;  // relative path inside the sweep directory ("" if none)
  std::string error_image;  // relative path inside the sweep directory ("" if none)
  // The reference it was measured against (relative path, "" if none), and whether it
  // differs visibly from it (the FrameComparison rule, against the reference).
  std::string reference_image;
  bool visible_vs_reference = false;
  // The configurations it can be compared with: the same device and reference (resolution,
  // light, framing), e.g. "ipad4, 2048x1536". Recommendations are made per group.
  std::string group;
  // Against the best configuration (lowest FLIP vs the reference) of its own technique in its
  // group: what its knob values cost on top of what the technique approximates.
  std::optional<FrameComparison> vs_finest;
  // Against the best configuration of the group over every technique.
  std::optional<FrameComparison> vs_best;
  // A sweep over a sequence: the frame-time distribution and temporal stability
  // (sequence_summary.h; frame_ms above is then the p95).
  std::optional<SequenceSummary> sequence;
};

// Cost of one pass per screen tile. Row-major, row 0 is the TOP row of the frame:
// ms[ty * tiles_x + tx]. `bottleneck` is empty or has one entry per tile.
struct TileHeatmap {
  int tiles_x = 0;
  int tiles_y = 0;
  int tile_size = 32;  // pixels per tile side
  std::vector<double> ms;
  std::vector<std::string> bottleneck;
  std::string pass_name;
  std::string config_id;  // configuration the map belongs to ("" if unspecified)
};

// How much the frame time moves when one uncertain model figure moves over its plausible
// range (hardware.md: uncertain constants are picked, documented, and shown here).
struct SensitivityRow {
  std::string figure;  // e.g. "gpu_clock_mhz"
  std::string unit;    // e.g. "MHz" ("" if dimensionless)
  double min_value = 0.0;
  double base_value = 0.0;
  double max_value = 0.0;
  double frame_ms_at_min = 0.0;
  double frame_ms_at_base = 0.0;
  double frame_ms_at_max = 0.0;
};

// One window of the frame cut out of several images, at 1:1 and magnified (paths relative to
// the sweep directory), for a recommendation's comparison panel.
struct CropWindow {
  std::string why;                            // e.g. "largest error against the reference"
  int x = 0, y = 0, size = 0;                 // the 1:1 window, in frame pixels
  int zoom_x = 0, zoom_y = 0, zoom_size = 0;  // the magnified window, inside it
  int zoom = 4;                               // magnification (nearest neighbour)
  std::vector<std::pair<std::string, std::string>> images;  // (what, path) at 1:1
  std::vector<std::pair<std::string, std::string>> zoomed;  // (what, path) magnified
};

// What a group's recommended configuration gives up against the best one and the reference:
// the full frames, and crops of the windows where it differs most.
struct ComparisonPanel {
  std::string group;
  std::string chosen;  // ids
  std::string best;
  std::string reference_image;  // full frames, relative paths
  std::string chosen_image;
  std::string best_image;
  double difference_gain = 1.0;  // difference images show |recommended - reference| x gain
  std::string colour_bar;        // PNG of the difference images' colour scale
  std::vector<CropWindow> windows;
};

struct SweepTable {
  std::string device;
  std::string scene;
  std::string resolution;  // e.g. "2048x1536"
  double budget_ms = 33.3;
  std::vector<ConfigResult> rows;
  std::optional<TileHeatmap> heatmap;
  std::vector<std::string> assumptions;
  std::vector<SensitivityRow> sensitivity;
  std::vector<ComparisonPanel> panels;  // one per group with a recommendation
};

// JSON mapping (nlohmann ADL hooks). from_json throws ResultsError naming the field at fault,
// e.g. "rows[3].frame_ms: expected a number".
void to_json(nlohmann::json& j, const CropWindow& v);
void from_json(const nlohmann::json& j, CropWindow& v);
void to_json(nlohmann::json& j, const ComparisonPanel& v);
void from_json(const nlohmann::json& j, ComparisonPanel& v);
void to_json(nlohmann::json& j, const FrameComparison& v);
void from_json(const nlohmann::json& j, FrameComparison& v);
void to_json(nlohmann::json& j, const PassCost& v);
void to_json(nlohmann::json& j, const ProgramCost& v);
void to_json(nlohmann::json& j, const ConfigResult& v);
void to_json(nlohmann::json& j, const TileHeatmap& v);
void to_json(nlohmann::json& j, const SensitivityRow& v);
void to_json(nlohmann::json& j, const SweepTable& v);
void from_json(const nlohmann::json& j, PassCost& v);
void from_json(const nlohmann::json& j, ConfigResult& v);
void from_json(const nlohmann::json& j, TileHeatmap& v);
void from_json(const nlohmann::json& j, SensitivityRow& v);
void from_json(const nlohmann::json& j, SweepTable& v);

// results.json read back (reports/sweep_json.h writes it); throws ResultsError naming the file
// and field.
SweepTable read_sweep_json(const std::string& path);

// Checks what JSON cannot: unique ids, finite non-negative times, heat map sizes.
// Throws ResultsError naming the field. Called by from_json and by the writers.
void validate_sweep_table(const SweepTable& table);

// The bottleneck of the configuration's most expensive pass ("" if it has no passes).
std::string dominant_bottleneck(const ConfigResult& row);

// The row's passes with same-named passes merged (e.g. blur iterations run as repeated
// "blur_h"/"blur_v" passes): ms and DRAM bytes summed, bottleneck of the costliest instance.
// First-appearance order.
std::vector<PassCost> merged_passes(const ConfigResult& row);

// Value of a knob, or "" if the row does not have it.
std::string knob_value(const ConfigResult& row, const std::string& knob);

}  // namespace skinsim::results
