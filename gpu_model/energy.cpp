#include "gpu_model/energy.h"

#include <algorithm>

#include "gpu_model/model_terms.h"
#include "util/check.h"

namespace skinsim::gpu_model {
namespace {

// Which end of the energy figures to price at.
enum class At { kValue, kMin, kMax };

double figure(const Figure& f, At at) {
  return at == At::kMin ? f.min : at == At::kMax ? f.max : f.value;
}

// Lane operations of one invocation, FP32 and FP16. A vector op is counted as four lanes
// (the model's vec4 issue; a vec2/vec3 op overstates), a scalar or special function as one.
struct LaneOps {
  double fp32 = 0.0;
  double fp16 = 0.0;
};

LaneOps lane_ops(const sim::OpProfile& o) {
  const auto d = [](std::uint32_t v) { return static_cast<double>(v); };
  return {
      4.0 * d(o.vector_ops - o.vector_ops_mediump) + d(o.scalar_ops - o.scalar_ops_mediump) +
          d(o.transcendental_ops - o.transcendental_ops_mediump),
      4.0 * d(o.vector_ops_mediump) + d(o.scalar_ops_mediump) + d(o.transcendental_ops_mediump)};
}

constexpr double kPjPerMj = 1e9;

EnergyParts pass_energy(const sim::PassCounters& pass, const PassTiming& timing,
                        const DeviceProfile& p, At at) {
  // Invocations per draw: the fragments this GPU class shades, and the vertices.
  std::vector<double> fragments(pass.draws.size(), 0.0);
  double visible = 0.0, shaded = 0.0;
  for (const sim::TileCounters& tile : pass.tiles) {
    for (const sim::DrawFragments& df : tile.shaded_by_draw) {
      const double n = fragments_shaded_on(df, p);
      fragments[df.draw] += n;
      visible += static_cast<double>(df.fragments_shaded);
      shaded += n;
    }
  }
  double fp32 = 0.0, fp16 = 0.0;
  for (std::size_t d = 0; d < pass.draws.size(); ++d) {
    const sim::DrawCounters& draw = pass.draws[d];
    const LaneOps frag = lane_ops(draw.fragment_profile);
    const LaneOps vert = lane_ops(draw.vertex_profile);
    const auto vertices = static_cast<double>(draw.vertices_shaded);
    fp32 += fragments[d] * frag.fp32 + vertices * vert.fp32;
    fp16 += fragments[d] * frag.fp16 + vertices * vert.fp16;
  }
  // Overdraw shaded without deferred HSR samples like the visible fragments (tile_cost.cpp).
  const double texture = texture_ops(pass.texture, p) * (visible > 0.0 ? shaded / visible : 1.0);

  EnergyParts e;
  e.dram = timing.dram.total() * figure(p.dram_pj_per_byte, at) / kPjPerMj;
  e.alu = (fp32 * figure(p.fp32_lane_op_pj, at) + fp16 * figure(p.fp16_lane_op_pj, at)) / kPjPerMj;
  e.texture = texture * figure(p.texture_sample_pj, at) / kPjPerMj;
  e.depth =
      static_cast<double>(pass.fragments_depth_tested) * figure(p.depth_test_pj, at) / kPjPerMj;
  return e;
}

}  // namespace

void EnergyParts::add(const EnergyParts& o) {
  dram += o.dram;
  alu += o.alu;
  texture += o.texture;
  depth += o.depth;
}

FrameEnergy estimate_energy(const std::vector<sim::PassCounters>& passes,
                            const std::vector<PassTiming>& timing, const DeviceProfile& p) {
  SKINSIM_CHECK_EQ(passes.size(), timing.size());
  FrameEnergy f;
  for (std::size_t i = 0; i < passes.size(); ++i) {
    PassEnergy e;
    e.name = passes[i].name;
    e.mj = pass_energy(passes[i], timing[i], p, At::kValue);
    e.low_mj = pass_energy(passes[i], timing[i], p, At::kMin).total();
    e.high_mj = pass_energy(passes[i], timing[i], p, At::kMax).total();
    f.mj.add(e.mj);
    f.low_mj += e.low_mj;
    f.high_mj += e.high_mj;
    f.passes.push_back(std::move(e));
  }
  return f;
}

double average_power_mw(double energy_mj, double frame_ms, double budget_ms) {
  const double ms = std::max(frame_ms, budget_ms);
  return ms > 0.0 ? energy_mj / ms * 1e3 : 0.0;
}

}  // namespace skinsim::gpu_model
