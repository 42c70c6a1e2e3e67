// `mobile`: the GPU Pro 5 screen-space irradiance pipeline (docs/pipeline.md), the primary
// technique; beyond lod_distance_m its single-pass shader takes over.
#include "pipeline/knob_types.h"
#include "pipeline/shader_variants.h"
#include "pipeline/shaders/blur.h"
#include "pipeline/shaders/irradiance.h"
#include "pipeline/shaders/skin.h"
#include "pipeline/shaders/surface_vs.h"
#include "pipeline/technique.h"
#include "pipeline/techniques/mobile/mobile_frame.h"

namespace skinsim::pipeline {

namespace {

FrameOutput render_mobile(const GpuScene& scene, const PipelineConfig& config,
                          const FrameLights& lights, sim::Gpu& gpu) {
  return render_mobile_frame(scene, config, lights, gpu, MobileMode::kAuto);
}

std::vector<sim::NamedProfile> mobile_programs() {
  using namespace pipeline::shaders;
  std::vector<sim::NamedProfile> s = {
      vertex_entry<PositionNormalVS>(), vertex_entry<DilatedPositionNormalVS>(),
      vertex_entry<BlurVS>(),           fragment_entry<IrradianceFS>(),
      fragment_entry<BlurFS>(),         fragment_entry<DepthAwareBlurFS>()};
  for (const auto& v : specular_variants<SkinFS>()) s.push_back(v);
  s.push_back(fragment_entry<SkinFS<GammaMode::kSrgb, SpecularModel::kKsLut>>());
  for (const auto& v : specular_variants<SkinLodFS>()) s.push_back(v);  // at LOD distance
  return s;
}

KnobSpec blur_iterations_knob() {
  KnobSpec k =
      swept_by(integer_knob("blur_iterations", "--blur-iterations", "Separable blur iterations",
                            {&PipelineConfig::mobile, &MobileParams::blur_iterations}, 1, 8),
               "--blur-iterations", "Blur iteration counts, e.g. 1,2,4");
  k.id_prefix = "blur";
  return k;
}

}  // namespace

const TechniqueSpec& mobile_technique() {
  static const TechniqueSpec spec{
      .name = "mobile",
      .passes = "irradiance, blur_h, blur_v, skin",
      .summary = "GPU Pro 5 screen-space irradiance pipeline (docs/pipeline.md)",
      .knobs =
          {
              swept_by(real_knob("scale", "--scale",
                                 "Integration-buffer size per axis as a fraction of the frame",
                                 {&PipelineConfig::mobile, &MobileParams::scale},
                                 {0.0, 1.0, true, false}),
                       "--scales",
                       "Integration-buffer scales, e.g. 1,0.5,0.25,0.125 (default sweep: those)"),
              blur_iterations_knob(),
              optional_real_knob("blur_width_mm", "--blur-width-mm",
                                 "Blur standard deviation on the skin in mm (auto: from the "
                                 "six-Gaussian profile)",
                                 {&PipelineConfig::mobile, &MobileParams::blur_width_mm},
                                 {0.0, 50.0, true, false}),
              real_knob("normal_offset_mm", "--normal-offset-mm",
                        "Irradiance-pass vertex push along the normal, mm",
                        {&PipelineConfig::mobile, &MobileParams::normal_offset_mm}, {0.0, 20.0}),
              real_knob("blur_follow_mm", "--blur-follow-mm",
                        "Depth-aware blur: taps on a surface this many mm nearer or farther "
                        "than the centre fade out (0: the blur ignores depth, as GPU Pro 5)",
                        {&PipelineConfig::mobile, &MobileParams::blur_follow_mm}, {0.0, 50.0}),
              real_knob("lod_distance_m", "--lod-distance",
                        "Camera distance in metres beyond which the single-pass LOD shader runs",
                        {&PipelineConfig::mobile, &MobileParams::lod_distance_m},
                        {0.0, 10000.0, true, false}),
          },
      .render = render_mobile,
      .shaders = mobile_programs,
      .host_ns_per_pixel = 680,
  };
  return spec;
}

}  // namespace skinsim::pipeline
