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

// A skin shader with each specular model, gamma 2.0.
template <template <GammaMode, SpecularModel> class Shader>
std::vector<sim::NamedProfile> specular_variants() {
  constexpr GammaMode kSquare = GammaMode::kSquare;
  return {entry(sim::make_fragment_program<Shader<kSquare, SpecularModel::kKsLut>>({})),
          entry(sim::make_fragment_program<Shader<kSquare, SpecularModel::kKs>>({})),
          entry(sim::make_fragment_program<Shader<kSquare, SpecularModel::kGgx>>({})),
          entry(sim::make_fragment_program<Shader<kSquare, SpecularModel::kDualGgx>>({}))};
}

void append(std::vector<sim::NamedProfile>& to, const std::vector<sim::NamedProfile>& more) {
  to.insert(to.end(), more.begin(), more.end());
}
}  // namespace

std::vector<sim::NamedProfile> shader_catalog() {
  using namespace shaders;
  constexpr GammaMode kSquare = GammaMode::kSquare;
  constexpr SpecularModel kKsLut = SpecularModel::kKsLut;
  BurleyFS::Uniforms burley_default;  // the profile counts the taps: the default count
  burley_default.count = PipelineConfig{}.burley_samples;
  std::vector<sim::NamedProfile> c = {
      entry(sim::make_vertex_program<SurfaceVS>({})),
      entry(sim::make_vertex_program<PositionNormalVS>({})),
      entry(sim::make_vertex_program<BlurVS>({})),
      entry(sim::make_fragment_program<IrradianceFS>({})),
      entry(sim::make_fragment_program<BlurFS>({})),
  };
  append(c, specular_variants<SkinFS>());
  c.push_back(entry(sim::make_fragment_program<SkinFS<GammaMode::kSrgb, kKsLut>>({})));
  append(c, specular_variants<SkinLodFS>());
  c.push_back(entry(sim::make_fragment_program<EyeFS>({})));
  c.push_back(entry(sim::make_fragment_program<BackgroundFS>({})));
  // Comparison techniques (docs/techniques.md), gamma 2.0.
  c.push_back(entry(sim::make_vertex_program<QuadVS>({})));
  c.push_back(entry(sim::make_vertex_program<UvSpaceVS>({})));
  c.push_back(entry(
      sim::make_fragment_program<PreintegratedFS<kSquare, kKsLut, CurvatureSource::kVertex>>({})));
  c.push_back(entry(
      sim::make_fragment_program<PreintegratedFS<kSquare, kKsLut, CurvatureSource::kDerivatives>>(
          {})));
  append(c, specular_variants<WrapFS>());
  c.push_back(entry(sim::make_fragment_program<DiffuseDepthFS>({})));
  c.push_back(entry(sim::make_fragment_program<BurleyFS>(burley_default)));
  c.push_back(entry(sim::make_fragment_program<SsssBlurFS>({})));
  c.push_back(entry(
      sim::make_fragment_program<DiffusedSkinFS<kSquare, kKsLut, DiffusionSource::kScreen>>({})));
  c.push_back(entry(sim::make_fragment_program<UvIrradianceFS>({})));
  c.push_back(entry(sim::make_fragment_program<UvCombineFS>({})));
  c.push_back(
      entry(sim::make_fragment_program<DiffusedSkinFS<kSquare, kKsLut, DiffusionSource::kUv>>({})));
  // Screen-space diffusion under an orthographic camera.
  c.push_back(entry(sim::make_fragment_program<DiffuseDepthOrthoFS>({})));
  c.push_back(entry(sim::make_fragment_program<BurleyOrthoFS>(burley_default)));
  c.push_back(entry(sim::make_fragment_program<SsssBlurOrthoFS>({})));
  return c;
}

}  // namespace skinsim::pipeline
