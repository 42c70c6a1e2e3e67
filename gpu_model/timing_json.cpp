#include "gpu_model/timing_json.h"

#include "gpu_model/energy.h"
#include "gpu_model/tile_memory.h"
#include "gpu_model/timing_table.h"

namespace skinsim::gpu_model {
namespace {

nlohmann::json per_unit(const std::array<double, kUnitCount>& values) {
  nlohmann::json j = nlohmann::json::object();
  for (int u = 0; u < kUnitCount; ++u) j[unit_name(static_cast<Unit>(u))] = values[u];
  return j;
}

nlohmann::json optional_ms(const std::optional<double>& ms) {
  return ms ? nlohmann::json(*ms) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json to_json(const DramBytes& b) {
  return {{"parameter_write", b.parameter_write},
          {"parameter_read", b.parameter_read},
          {"texture", b.texture},
          {"color_load", b.color_load},
          {"color_store", b.color_store},
          {"depth_load", b.depth_load},
          {"depth_store", b.depth_store},
          {"total", b.total()}};
}

nlohmann::json to_json(const FrameTiming& frame) {
  nlohmann::json passes = nlohmann::json::array();
  for (std::size_t i = 0; i < frame.passes.size(); ++i) {
    const PassTiming& p = frame.passes[i];
    const PassSlot& s = frame.schedule[i];
    passes.push_back({
        {"name", p.name},
        {"ms", s.exposed_ms},
        {"standalone_ms", p.standalone_ms},
        {"ta_ms", p.ta_ms},
        {"render_ms", p.render_ms},
        {"makespan_ms", p.makespan_ms},
        {"balance", p.balance},
        {"bottleneck", unit_name(p.bottleneck)},
        {"utilisation", per_unit(p.utilisation)},
        {"busy_ms", per_unit(p.busy_ms)},
        {"dram_bytes", to_json(p.dram)},
        {"schedule",
         {{"ta_start_ms", s.ta_start_ms},
          {"ta_end_ms", s.ta_end_ms},
          {"render_start_ms", s.render_start_ms},
          {"render_end_ms", s.render_end_ms}}},
    });
  }
  return {{"device", frame.device},
          {"frame_ms", frame.frame_ms},
          {"fps", frame.fps},
          {"pipeline_ms", frame.pipeline_ms},
          {"bandwidth_ms", frame.bandwidth_ms},
          {"dram_wait_ms", frame.dram_wait_ms},
          {"dram_bytes", to_json(frame.dram)},
          {"passes", passes}};
}

nlohmann::json to_json(const EnergyParts& e) {
  return {{"dram", e.dram},
          {"alu", e.alu},
          {"texture", e.texture},
          {"depth", e.depth},
          {"total", e.total()}};
}

nlohmann::json energy_to_json(const FrameTiming& frame, double budget_ms) {
  const FrameEnergy& e = frame.energy;
  nlohmann::json passes = nlohmann::json::array();
  for (const PassEnergy& p : e.passes) {
    passes.push_back(
        {{"name", p.name}, {"mj", to_json(p.mj)}, {"low_mj", p.low_mj}, {"high_mj", p.high_mj}});
  }
  return {{"frame_mj", e.mj.total()},
          {"low_mj", e.low_mj},
          {"high_mj", e.high_mj},
          {"mj", to_json(e.mj)},
          {"budget_ms", budget_ms},
          {"average_power_mw", average_power_mw(e.mj.total(), frame.frame_ms, budget_ms)},
          {"passes", passes}};
}

nlohmann::json tiles_to_json(const PassTiming& pass) {
  nlohmann::json tiles = nlohmann::json::array();
  for (const TileTiming& t : pass.tiles) {
    tiles.push_back({{"x", t.tile_x},
                     {"y", t.tile_y},
                     {"core", t.core},
                     {"start_ms", t.start_ms},
                     {"ms", t.ms},
                     {"bottleneck", unit_name(t.bottleneck)}});
  }
  return tiles;
}

nlohmann::json to_json(const std::vector<SensitivityRow>& rows) {
  nlohmann::json j = nlohmann::json::array();
  for (const SensitivityRow& r : rows) {
    j.push_back(
        {{"figure", r.figure},
         {"unit", r.unit},
         {"confidence", confidence_name(r.confidence)},
         {"value", {r.value_min, r.value_base, r.value_max}},
         {"frame_ms", {optional_ms(r.frame_ms_min), r.frame_ms_base, optional_ms(r.frame_ms_max)}},
         {"needs_recount", r.needs_recount}});
  }
  return j;
}

nlohmann::json device_json(const DeviceProfile& p) {
  const DeviceKeyFigures k = key_figures(p);
  return {{"name", p.name},
          {"source_path", p.source_path},
          {"device", p.device},
          {"soc", p.soc},
          {"gpu", p.gpu},
          {"display", {k.display_width, k.display_height}},
          {"cores", k.cores},
          {"pipes_per_core", k.pipes_per_core},
          {"clock_mhz", k.clock_mhz},
          {"peak_gflops", k.peak_gflops},
          {"tmus", k.tmus},
          {"dram_peak_gb_per_s", k.dram_peak_gb_per_s},
          {"dram_achievable_gb_per_s", k.dram_achievable_gb_per_s},
          {"tile", {k.tile_width, k.tile_height}},
          {"texture_cache_kib_per_core", k.texture_cache_kib},
          {"class", gpu_class_name(p.gpu_class)},
          {"tile_memory_bytes", p.tile_memory_bytes.value},
          {"tile_at_32_bytes_per_pixel", {k.tile_at_32_bpp.width, k.tile_at_32_bpp.height}},
          {"fp16_rate", k.fp16_rate},
          {"framebuffer_compression", p.framebuffer_compression.value},
          {"hsr_overdraw_removed", p.hsr_overdraw_removed.value}};
}

}  // namespace skinsim::gpu_model
