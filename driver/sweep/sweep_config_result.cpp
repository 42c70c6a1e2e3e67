#include "driver/sweep/sweep_config_result.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "driver/frame/frame_passes.h"
#include "gpu_model/sensitivity.h"
#include "gpu_model/timing.h"
#include "io/json_input.h"
#include "quality/metrics.h"

namespace skinsim::driver {

namespace {

// 2: frame_ms_low/high, FLIP percentiles and visibility; 3: pass ms = share of the frame, the
// pass schedule, dram_wait; 4: the images' digests; 5: energy per frame and its range
constexpr int kFormatVersion = 5;

}  // namespace

results::ConfigResult config_row(const SweepConfig& config, const FrameResult& frame,
                                 const FrameQuality& quality, const std::string& frame_image,
                                 const std::string& error_image,
                                 const std::string& reference_image) {
  results::ConfigResult row;
  row.id = config.id;
  row.label = config.label;
  for (const auto& [knob, value] : all_knobs(config, frame.config.width, frame.config.height)) {
    row.knobs[knob] = value;
  }
  row.reference_image = reference_image;
  const double visible_px =
      quality.metrics.at(quality.has_skin_metrics() ? "visible_skin_px" : "visible_frame_px");
  row.visible_vs_reference = visible_px >= quality::flip_visible_area_pixels();
  row.frame_ms = frame.timing.frame_ms;
  row.frame_ms_low = frame.range.low;
  row.frame_ms_high = frame.range.high;
  row.fps = frame.timing.fps;
  row.dram_bytes = frame.timing.dram_bytes;
  row.energy_mj = frame.timing.energy.mj.total();
  row.energy_mj_low = frame.timing.energy.low_mj;
  row.energy_mj_high = frame.timing.energy.high_mj;
  row.passes = pass_costs(frame.timing);
  for (const sim::PassCounters& pass : frame.output.passes) {
    for (const sim::DrawCounters& d : pass.draws) {
      if (d.fragments_shaded == 0) continue;
      const auto same = [&](const results::ProgramCost& c) {
        return c.pass == pass.name && c.program == d.fragment_program;
      };
      auto it = std::find_if(row.programs.begin(), row.programs.end(), same);
      if (it == row.programs.end()) {
        const sim::OpProfile& p = d.fragment_profile;
        row.programs.push_back({pass.name, d.fragment_program, 0.0, static_cast<int>(p.vector_ops),
                                static_cast<int>(p.scalar_ops),
                                static_cast<int>(p.transcendental_ops),
                                static_cast<int>(p.texture_reads_independent),
                                static_cast<int>(p.texture_reads_dependent)});
        it = std::prev(row.programs.end());
      }
      it->fragments += static_cast<double>(d.fragments_shaded);
    }
  }
  // The table holds finite numbers only (JSON has no infinity): PSNR of a frame identical to
  // the reference is +inf, and such a cell is left empty rather than given a made-up value.
  for (const auto& [name, value] : quality.metrics) {
    if (std::isfinite(value)) row.quality[name] = value;
  }
  row.frame_image = frame_image;
  row.error_image = error_image;
  return row;
}

std::optional<results::TileHeatmap> pass_heatmap(const FrameResult& frame, const std::string& pass,
                                                 const std::string& config_id) {
  for (std::size_t i = 0; i < frame.timing.passes.size(); ++i) {
    const gpu_model::PassTiming& timing = frame.timing.passes[i];
    if (timing.name != pass) continue;
    const sim::PassCounters& counters = frame.output.passes.at(i);
    results::TileHeatmap map;
    map.tiles_x = counters.tiles_x;
    map.tiles_y = counters.tiles_y;
    map.tile_size = counters.tile_size;
    map.pass_name = pass;
    map.config_id = config_id;
    const std::size_t n = static_cast<std::size_t>(map.tiles_x) * map.tiles_y;
    map.ms.assign(n, 0.0);
    map.bottleneck.assign(n, gpu_model::unit_name(gpu_model::Unit::kOverhead));
    // Tile rows count from the top of the frame, as the images and the heat map do.
    for (const gpu_model::TileTiming& t : timing.tiles) {
      const std::size_t k = static_cast<std::size_t>(t.tile_y) * map.tiles_x + t.tile_x;
      if (k >= n) continue;
      map.ms[k] = t.ms;
      map.bottleneck[k] = gpu_model::unit_name(t.bottleneck);
    }
    return map;
  }
  return std::nullopt;
}

void add_sensitivity(const FrameResult& frame, const gpu_model::DeviceProfile& device,
                     StoredConfig& stored) {
  bool skipped_recount = false;
  for (const gpu_model::SensitivityRow& s : gpu_model::sensitivity(frame.output.passes, device)) {
    stored.assumptions.push_back(
        fmt::format("{} = {} {} ({} confidence; plausible {} to {})", s.figure, s.value_base,
                    s.unit, gpu_model::confidence_name(s.confidence), s.value_min, s.value_max));
    if (!s.frame_ms_min || !s.frame_ms_max) {
      skipped_recount = true;
      continue;
    }
    stored.sensitivity.push_back({s.figure, s.unit, s.value_min, s.value_base, s.value_max,
                                  *s.frame_ms_min, s.frame_ms_base, *s.frame_ms_max});
  }
  if (skipped_recount) {
    stored.assumptions.push_back(
        "Figures that change what the emulator counts (texture cache, tile size) are not "
        "re-emulated in sweeps; `skinsim run --sensitivity` gives their effect.");
  }
}

nlohmann::json to_json(const StoredConfig& stored) {
  nlohmann::json j = {{"format", kFormatVersion},
                      {"fingerprint", stored.fingerprint},
                      {"row", stored.row},
                      {"sensitivity", stored.sensitivity},
                      {"assumptions", stored.assumptions},
                      {"files", stored.files}};
  if (stored.heatmap) j["heatmap"] = *stored.heatmap;
  return j;
}

std::optional<StoredConfig> read_stored_config(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) return std::nullopt;
  const nlohmann::json j =
      io::parse_json_or_discarded(io::read_regular_file(path, "stored sweep result"));
  if (j.is_discarded() || !j.is_object() || j.value("format", 0) != kFormatVersion) {
    return std::nullopt;
  }
  try {
    StoredConfig s;
    s.fingerprint = j.at("fingerprint");
    s.row = j.at("row").get<results::ConfigResult>();
    s.sensitivity = j.at("sensitivity").get<std::vector<results::SensitivityRow>>();
    s.assumptions = j.at("assumptions").get<std::vector<std::string>>();
    s.files = j.at("files").get<std::map<std::string, std::string>>();
    if (j.contains("heatmap")) s.heatmap = j["heatmap"].get<results::TileHeatmap>();
    return s;
  } catch (const std::exception&) {
    return std::nullopt;  // incomplete or from another version: compute it again
  }
}

}  // namespace skinsim::driver
