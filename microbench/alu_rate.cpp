// ALU throughput: a full-screen pass whose fragment program is a long chain of vec4
// multiply-adds, so the USSE pipes are the only busy unit.
#include <fmt/format.h>

#include <stdexcept>

#include "microbench/benchmarks.h"
#include "microbench/meshes.h"
#include "microbench/shaders.h"

namespace skinsim::microbench {

MicrobenchResult run_alu_mad_chain(BenchContext& ctx) {
  const MicrobenchOptions& o = ctx.options();
  const Mesh quad = grid_mesh(1, 1, 0.0f);
  shaders::MadChainFS::Uniforms u;
  u.vector_ops = o.alu_vector_ops;
  sim::RenderTarget target("alu", o.width, o.height, sim::TexelFormat::kRGBA8);
  sim::RenderPassDesc pass;
  pass.name = "alu_mad_chain";
  pass.color = &target;
  sim::DrawCall d;
  d.geometry = quad.geometry();
  d.vertex_program = sim::make_vertex_program<shaders::TransformUvVS>({});
  d.fragment_program = sim::make_fragment_program<shaders::MadChainFS>(u);
  pass.draws.push_back(d);

  // FLOP are counted from the recorded profile, which must be the MAD chain and nothing
  // else for "8 FLOP per vector op" to hold.
  const sim::OpProfile& ops = d.fragment_program->profile();
  if (ops.vector_ops != static_cast<std::uint32_t>(o.alu_vector_ops) || ops.scalar_ops != 0 ||
      ops.transcendental_ops != 0 || ops.texture_reads() != 0) {
    throw std::logic_error(fmt::format(
        "alu_mad_chain: shader profile has {} vector, {} scalar, {} transcendental ops and {} "
        "texture reads; expected exactly {} vector MADs",
        ops.vector_ops, ops.scalar_ops, ops.transcendental_ops, ops.texture_reads(),
        o.alu_vector_ops));
  }
  MeasuredPass m = ctx.run(pass);

  const double flop =
      static_cast<double>(m.counters.fragments_shaded) * ops.vector_ops * kFlopPerVectorMad;
  std::string shows = fmt::format(
      "{} fragments x {} vec4 MADs ({:g} FLOP each) at {:g} cycles per vector op: USSE issue "
      "rate",
      m.counters.fragments_shaded, ops.vector_ops, kFlopPerVectorMad,
      ctx.profile().vector_op_cycles.value);
  return make_result("alu_mad_chain", "GFLOPS", flop * 1e-9, alu_peak_gflops(ctx.profile()),
                     std::move(m), std::move(shows));
}

}  // namespace skinsim::microbench
