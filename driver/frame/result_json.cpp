#include "driver/frame/result_json.h"

#include "gpu_model/timing_json.h"
#include "io/atomic_file.h"
#include "pipeline/config.h"
#include "quality/json_value.h"
#include "scene/scene_scale.h"

namespace skinsim::driver {

using nlohmann::json;

json to_json(const sim::OpProfile& p) {
  return {{"vector_ops", p.vector_ops},
          {"scalar_ops", p.scalar_ops},
          {"transcendental_ops", p.transcendental_ops},
          {"vector_ops_mediump", p.vector_ops_mediump},
          {"scalar_ops_mediump", p.scalar_ops_mediump},
          {"transcendental_ops_mediump", p.transcendental_ops_mediump},
          {"texture_reads_independent", p.texture_reads_independent},
          {"texture_reads_dependent", p.texture_reads_dependent},
          {"input_floats", p.input_floats},
          {"output_floats", p.output_floats}};
}

namespace {

json texture_json(const sim::TextureCounters& t) {
  return {
      {"samples_nearest", t.samples_by_filter[0]},
      {"samples_bilinear", t.samples_by_filter[1]},
      {"samples_trilinear", t.samples_by_filter[2]},
      {"samples_dependent", t.samples_dependent},
      {"samples_wide_format", t.samples_wide_format},
      {"texels_touched", t.texels_touched},
      {"cache_line_accesses", t.cache_line_accesses},
      {"cache_misses", t.cache_misses},
      {"cache_miss_rate",
       t.cache_line_accesses ? static_cast<double>(t.cache_misses) / t.cache_line_accesses : 0.0},
      {"dram_bytes", t.dram_bytes}};
}

}  // namespace

json to_json(const sim::PassCounters& c) {
  json draws = json::array();
  for (const sim::DrawCounters& d : c.draws) {
    draws.push_back({{"vertex_program", d.vertex_program},
                     {"fragment_program", d.fragment_program},
                     {"vertex_profile", to_json(d.vertex_profile)},
                     {"fragment_profile", to_json(d.fragment_profile)},
                     {"blended", d.blended},
                     {"vertices_shaded", d.vertices_shaded},
                     {"triangles_in", d.triangles_in},
                     {"fragments_shaded", d.fragments_shaded}});
  }
  json j = {{"name", c.name},
            {"width", c.width},
            {"height", c.height},
            {"tile_size", c.tile_size},
            {"tiles_x", c.tiles_x},
            {"tiles_y", c.tiles_y},
            {"cores", c.cores},
            {"tiler",
             {{"vertices_shaded", c.vertices_shaded},
              {"triangles_in", c.triangles_in},
              {"triangles_culled_backface", c.triangles_culled_backface},
              {"triangles_culled_frustum", c.triangles_culled_frustum},
              {"triangles_culled_degenerate", c.triangles_culled_degenerate},
              {"triangles_clipped", c.triangles_clipped},
              {"triangles_binned", c.triangles_binned},
              {"tile_refs", c.tile_refs},
              {"varying_floats_per_vertex", c.varying_floats_per_vertex},
              {"tiles_empty", c.tiles_empty},
              {"tiles_partial", c.tiles_partial},
              {"tiles_full", c.tiles_full}}},
            {"renderer",
             {{"tiles_rendered", c.tiles_rendered},
              {"fragments_depth_tested", c.fragments_depth_tested},
              {"fragments_shaded", c.fragments_shaded},
              {"fragments_blended", c.fragments_blended},
              {"hsr_flushes", c.hsr_flushes},
              {"color_load_bytes", c.color_load_bytes},
              {"color_store_bytes", c.color_store_bytes},
              {"depth_load_bytes", c.depth_load_bytes},
              {"depth_store_bytes", c.depth_store_bytes}}},
            {"texture", texture_json(c.texture)},
            {"draws", draws}};
  // Only a multisampled pass has the block, so a 1x pass reads as it always has.
  if (c.samples > 1) {
    j["msaa"] = {{"samples", c.samples},
                 {"tile_bytes_per_sample", c.tile_bytes_per_sample},
                 {"samples_covered", c.samples_covered},
                 {"samples_in_tile", c.samples_in_tile},
                 {"resolves", c.resolves}};
  }
  return j;
}

json scene_scale_json(const scene::Scene& s) {
  const char* source = "--units-per-mm";
  switch (s.units_source) {
    case scene::UnitsSource::kGiven:
      break;
    case scene::UnitsSource::kFile:
      source = "file metres";
      break;
    case scene::UnitsSource::kHeadHeight:
      source = "head height";
      break;
    case scene::UnitsSource::kBoxHeight:
      source = "bounding box";
      break;
  }
  json j = {{"units_per_mm", s.units_per_mm},
            {"source", source},
            {"typical_head_mm", scene::kTypicalHeadMm}};
  if (s.head) {
    const auto point = [](const glm::vec3& p) { return json::array({p.x, p.y, p.z}); };
    j["head"] = {{"height_units", s.head->height()},
                 {"height_mm", s.head->height() / s.units_per_mm},
                 {"crown", point(s.head->crown)},
                 {"nose_tip", point(s.head->nose_tip)},
                 {"chin", point(s.head->chin)}};
  }
  j["summary"] = scene::describe_scale(s);
  return j;
}

json frame_result_json(const FrameResult& r, const std::string& scene_label) {
  json config = json::object();
  for (const std::string& key : pipeline::config_field_names()) {
    config[key] = pipeline::get_config_field(r.config, key);
  }
  json counters = json::array();
  for (const sim::PassCounters& p : r.output.passes) counters.push_back(to_json(p));
  json timing = gpu_model::to_json(r.timing);
  timing["frame_ms_range"] = {{"low", r.range.low},
                              {"high", r.range.high},
                              {"uncertain_figures", r.range.figures},
                              {"figures_needing_rerender_left_out", r.range.left_out}};
  return {{"tool", "skinsim"},
          {"scene", scene_label},
          {"config", config},
          {"technique", r.output.decisions},
          {"counters", counters},
          {"timing", timing},
          {"energy", gpu_model::energy_to_json(r.timing)}};
}

namespace {

// "quality": each metric (non-finite ones as strings, quality/json_value.h), and why the skin
// metrics are missing when the reference shows no skin.
json quality_json(const FrameQuality& q, const std::string& no_skin) {
  json metrics = json::object();
  for (const auto& [name, value] : q.metrics) metrics[name] = quality::metric_to_json(value);
  if (!q.has_skin_metrics()) metrics["skin_metrics_unavailable"] = no_skin;
  return metrics;
}

}  // namespace

json run_result_json(const FrameResult& result, const std::string& scene_label,
                     const RunRecord& record) {
  json j = frame_result_json(result, scene_label);
  j["device"] = record.device;
  if (record.scene != nullptr) j["scene_scale"] = scene_scale_json(*record.scene);
  if (record.sequence) j["sequence"] = *record.sequence;
  if (record.reference) j["reference"] = *record.reference;
  if (record.quality != nullptr) j["quality"] = quality_json(*record.quality, record.no_skin);
  if (record.sensitivity) j["sensitivity"] = gpu_model::to_json(*record.sensitivity);
  if (record.truth) j["truth"] = *record.truth;
  j["warnings"] = record.warnings;
  return j;
}

void write_result_json(const json& j, const std::filesystem::path& path) {
  io::write_file_atomically(path.string(),
                            j.dump(2, ' ', false, json::error_handler_t::replace) + "\n");
}

}  // namespace skinsim::driver
