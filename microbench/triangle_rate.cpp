// Triangle throughput: a dense grid of tiny triangles through the tiler (TA). Culled
// variants (outside the view volume, back-facing) isolate triangle setup and culling;
// the visible variant adds binning and the parameter-buffer round trip through DRAM.
#include <fmt/format.h>

#include "microbench/benchmarks.h"
#include "microbench/meshes.h"
#include "microbench/shaders.h"

namespace skinsim::microbench {
namespace {

enum class Placement { kVisible, kOffscreen, kBackface };

const char* pass_name(Placement p) {
  switch (p) {
    case Placement::kVisible:
      return "triangles_visible";
    case Placement::kOffscreen:
      return "triangles_offscreen";
    case Placement::kBackface:
      return "triangles_backface";
  }
  return "";
}

MeasuredPass triangle_pass(BenchContext& ctx, Placement placement) {
  const MicrobenchOptions& o = ctx.options();
  const Mesh grid = grid_mesh(
      o.width / o.triangle_cell_pixels, o.height / o.triangle_cell_pixels, 0.0f,
      placement == Placement::kBackface ? Winding::kClockwise : Winding::kCounterClockwise);
  shaders::TransformVS::Uniforms u;
  // Shifted right by 3 clip units, the grid spans x in [2, 4]: entirely outside x <= w.
  if (placement == Placement::kOffscreen) u.transform[3][0] = 3.0f;
  sim::RenderTarget target("triangles", o.width, o.height, sim::TexelFormat::kRGBA8);
  sim::RenderPassDesc pass;
  pass.name = pass_name(placement);
  pass.color = &target;
  sim::DrawCall d;
  d.geometry = grid.geometry();
  d.vertex_program = sim::make_vertex_program<shaders::TransformVS>(u);
  d.fragment_program = sim::make_fragment_program<shaders::FlatColorFS>({});
  pass.draws.push_back(d);
  return ctx.run(pass);
}

MicrobenchResult triangle_result(BenchContext& ctx, Placement placement, MeasuredPass m,
                                 std::string shows) {
  const double work = static_cast<double>(m.counters.triangles_in) * 1e-6;
  return make_result(pass_name(placement), "Mtri/s", work, tiler_peak(ctx.profile()), std::move(m),
                     std::move(shows));
}

}  // namespace

MicrobenchResult run_triangles_visible(BenchContext& ctx) {
  MeasuredPass m = triangle_pass(ctx, Placement::kVisible);
  const auto& c = m.counters;
  const double cell = ctx.options().triangle_cell_pixels;
  std::string shows = fmt::format(
      "{} visible triangles of {:g} px each, {} binned with {:.2f} tile refs per triangle: "
      "setup, binning and {:.1f} MB of parameter buffer written and read back",
      c.triangles_in, cell * cell / 2.0, c.triangles_binned,
      c.triangles_binned ? static_cast<double>(c.tile_refs) / c.triangles_binned : 0.0,
      (m.timing.dram.parameter_write + m.timing.dram.parameter_read) * 1e-6);
  return triangle_result(ctx, Placement::kVisible, std::move(m), std::move(shows));
}

MicrobenchResult run_triangles_offscreen(BenchContext& ctx) {
  MeasuredPass m = triangle_pass(ctx, Placement::kOffscreen);
  std::string shows = fmt::format(
      "{} triangles outside the view volume, {} culled by the tiler before binning: the "
      "setup/cull rate",
      m.counters.triangles_in, m.counters.triangles_culled_frustum);
  return triangle_result(ctx, Placement::kOffscreen, std::move(m), std::move(shows));
}

MicrobenchResult run_triangles_backface(BenchContext& ctx) {
  MeasuredPass m = triangle_pass(ctx, Placement::kBackface);
  std::string shows =
      fmt::format("{} back-facing triangles on screen, {} culled after setup: the setup/cull rate",
                  m.counters.triangles_in, m.counters.triangles_culled_backface);
  return triangle_result(ctx, Placement::kBackface, std::move(m), std::move(shows));
}

}  // namespace skinsim::microbench
