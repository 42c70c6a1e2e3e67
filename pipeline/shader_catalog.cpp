#include "pipeline/shader_catalog.h"

#include "pipeline/shaders/background.h"
#include "pipeline/shaders/blur.h"
#include "pipeline/shaders/diffused_skin.h"
#include "pipeline/shaders/eye.h"
#include "pipeline/shaders/irradiance.h"
#include "pipeline/shaders/preintegrated.h"
#include "pipeline/shaders/screen_diffusion.h"
#include "pipeline/shaders/skin.h"
#include "pipeline/shaders/texture_space.h"
#include "pipeline/shaders/wrap.h"
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
  constexpr GammaMode kSquare = GammaMode::kSquare;
  constexpr SpecularModel kKsLut = SpecularModel::kKsLut;
  BurleyFS::Uniforms burley_default;  // the profile counts the taps: the default count
  burley_default.count = PipelineConfig{}.burley_samples;
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
      // Comparison techniques (docs/techniques.md), gamma 2.0; the specular models on wrap.
      entry(sim::make_vertex_program<QuadVS>({})),
      entry(sim::make_vertex_program<UvSpaceVS>({})),
      entry(sim::make_fragment_program<PreintegratedFS<kSquare, kKsLut, CurvatureSource::kVertex>>(
          {})),
      entry(sim::make_fragment_program<
            PreintegratedFS<kSquare, kKsLut, CurvatureSource::kDerivatives>>({})),
      entry(sim::make_fragment_program<WrapFS<kSquare, kKsLut>>({})),
      entry(sim::make_fragment_program<WrapFS<kSquare, SpecularModel::kKs>>({})),
      entry(sim::make_fragment_program<WrapFS<kSquare, SpecularModel::kGgx>>({})),
      entry(sim::make_fragment_program<WrapFS<kSquare, SpecularModel::kDualGgx>>({})),
      entry(sim::make_fragment_program<DiffuseDepthFS>({})),
      entry(sim::make_fragment_program<BurleyFS>(burley_default)),
      entry(sim::make_fragment_program<SsssBlurFS>({})),
      entry(sim::make_fragment_program<DiffusedSkinFS<kSquare, kKsLut, DiffusionSource::kScreen>>(
          {})),
      entry(sim::make_fragment_program<UvIrradianceFS>({})),
      entry(sim::make_fragment_program<UvCombineFS>({})),
      entry(sim::make_fragment_program<DiffusedSkinFS<kSquare, kKsLut, DiffusionSource::kUv>>({})),
  };
}

}  // namespace skinsim::pipeline
