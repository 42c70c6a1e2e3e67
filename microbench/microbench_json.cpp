#include "gpu_model/timing_json.h"
#include "microbench/microbench.h"

namespace skinsim::microbench {

nlohmann::json to_json(const std::vector<MicrobenchResult>& results) {
  nlohmann::json rows = nlohmann::json::array();
  for (const MicrobenchResult& r : results) {
    const sim::PassCounters& c = r.counters;
    rows.push_back({
        {"name", r.name},
        {"value", r.value},
        {"unit", r.unit},
        {"peak", r.peak},
        {"peak_basis", r.peak_basis},
        {"ratio", r.ratio},
        {"bottleneck", gpu_model::unit_name(r.bottleneck)},
        {"pass_ms", r.pass_ms},
        {"shows", r.shows},
        {"counters",
         {{"width", c.width},
          {"height", c.height},
          {"triangles_in", c.triangles_in},
          {"triangles_binned", c.triangles_binned},
          {"tile_refs", c.tile_refs},
          {"fragments_depth_tested", c.fragments_depth_tested},
          {"fragments_shaded", c.fragments_shaded},
          {"fragments_blended", c.fragments_blended},
          {"texture_samples", c.texture.samples()},
          {"texture_cache_misses", c.texture.cache_misses}}},
        {"dram_bytes", gpu_model::to_json(r.timing.dram)},
    });
  }
  return rows;
}

}  // namespace skinsim::microbench
