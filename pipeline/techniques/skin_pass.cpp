#include "pipeline/techniques/skin_pass.h"

#include "pipeline/bake/brdf_lut_encoding.h"
#include "pipeline/diffusion.h"
#include "pipeline/shaders/background.h"
#include "pipeline/shaders/eye.h"
#include "pipeline/shaders/technique_bindings.h"

namespace skinsim::pipeline {

using scene::MaterialKind;

shaders::TechniqueUniforms technique_uniforms(const View& view, const PipelineConfig& cfg,
                                              const FrameLights& lights, const GpuMaterial& mat) {
  shaders::TechniqueUniforms u;
  u.eye = view.eye;
  u.lights = lights.uniforms();
  u.albedo_factor = glm::vec3(mat.base_color_factor);
  u.layer_mix = skin_layer_split().wide_fraction;
  u.reflectivity = mat.reflectivity;
  u.specular_intensity = cfg.specular_intensity;
  u.lobe1_weight = cfg.lobe1.weight;
  u.lobe2_weight = cfg.lobe2.weight;
  u.lobe1_roughness = cfg.lobe1.roughness;
  u.lobe2_roughness = cfg.lobe2.roughness;
  u.lut_lod = bake::brdf_lut_lod(1.0f);  // the config's own roughness
  u.wrap = cfg.wrap.amount;
  return u;
}

sim::PassCounters skin_framebuffer_pass(const GpuScene& gs, const View& view,
                                        const FrameLights& lights, Transmission transmission,
                                        const SkinShading& shading, int msaa,
                                        sim::RenderTarget& frame, sim::Gpu& gpu) {
  // Eyes and background share the skin's vertex program (one program for the render).
  auto vs = sim::make_vertex_program<shaders::SurfaceVS>(
      {view.view_proj, 0.0f, lights.vertex_uniforms(transmission)});
  sim::RenderPassDesc pass;
  pass.name = "skin";
  pass.color = &frame;
  pass.clear_color = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  pass.samples = msaa;
  // Draw order: background, eyes, skin. HSR makes the order irrelevant to shading cost.
  for (const MaterialKind kind : {MaterialKind::kOther, MaterialKind::kEye, MaterialKind::kSkin}) {
    for (const GpuMesh& m : gs.meshes()) {
      const GpuMaterial& mat = gs.materials()[m.material];
      if (mat.kind != kind) continue;
      sim::DrawCall d;
      d.geometry = m.geometry;
      d.vertex_program = vs;
      const glm::vec3 factor(mat.base_color_factor);
      d.textures.textures[shaders::TechniqueBindings::kAlbedo] = mat.base_color;
      lights.bind(d);
      if (kind == MaterialKind::kOther) {
        d.fragment_program =
            sim::make_fragment_program<shaders::BackgroundFS>({lights.uniforms(), factor});
      } else if (kind == MaterialKind::kEye) {
        shaders::EyeFS::Uniforms u;
        u.eye = view.eye;
        u.lights = lights.uniforms();
        u.albedo_factor = factor;
        d.fragment_program = sim::make_fragment_program<shaders::EyeFS>(u);
        d.textures.cubes[shaders::EyeFS::kEnvironment] = &gs.environment();
      } else {
        d.textures.textures[shaders::TechniqueBindings::kNormalMap] = mat.normal;
        d.textures.cubes[shaders::TechniqueBindings::kEnvironment] = &gs.environment_diffuse();
        shading(mat, d);
      }
      pass.draws.push_back(d);
    }
  }
  return gpu.execute(pass);
}

}  // namespace skinsim::pipeline
