#include "pipeline/shader_catalog.h"

#include "pipeline/shaders/background.h"
#include "pipeline/shaders/blur.h"
#include "pipeline/shaders/eye.h"
#include "pipeline/shaders/irradiance.h"
#include "pipeline/shaders/skin.h"
#include "sim/program.h"

namespace skinsim::pipeline {

namespace {
template <class Program>
sim::NamedProfile entry(const Program& p) {
  return {p->name(), p->profile()};
}
}  // namespace

std::vector<sim::NamedProfile> shader_catalog() {
  using namespace shaders;
  return {
      entry(sim::make_vertex_program<SurfaceVS>({})),
      entry(sim::make_vertex_program<PositionNormalVS>({})),
      entry(sim::make_vertex_program<BlurVS>({})),
      entry(sim::make_fragment_program<IrradianceFS>({})),
      entry(sim::make_fragment_program<BlurFS>({})),
      entry(sim::make_fragment_program<SkinFS<GammaMode::kSquare>>({})),
      entry(sim::make_fragment_program<SkinFS<GammaMode::kSrgb>>({})),
      entry(sim::make_fragment_program<SkinLodFS<GammaMode::kSquare>>({})),
      entry(sim::make_fragment_program<EyeFS>({})),
      entry(sim::make_fragment_program<BackgroundFS>({})),
  };
}

}  // namespace skinsim::pipeline
