#include "driver/truth/truth_scene.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "image/image.h"
#include "io/atomic_file.h"
#include "pipeline/bake/brdf_lut.h"
#include "pipeline/bake/dipole.h"
#include "pipeline/bake/skin_profile.h"
#include "pipeline/brdf_lut_texture.h"
#include "pipeline/lighting.h"
#include "pipeline/shaders/eye.h"
#include "util/unorm8.h"

namespace skinsim::driver {

namespace {

using nlohmann::json;

// The reference's lights are discs 1 degree in radius (pipeline/reference/reference.cpp):
// Cycles' sun lamps of the same angular diameter.
constexpr float kLightRadiusRad = 0.0175f;

json vec(const glm::vec3& v) {
  return json::array({v.x, v.y, v.z});
}

// Schlick's F0 as the index of refraction Cycles' Fresnel node takes: F0 = ((n-1)/(n+1))^2.
float ior_from_f0(float f0) {
  const float s = std::sqrt(f0);
  return (1.0f + s) / (1.0f - s);
}

template <class T>
void append(std::string& out, const std::vector<T>& values) {
  static_assert(std::endian::native == std::endian::little, "meshes.bin is little-endian");
  const std::size_t at = out.size();
  out.resize(at + values.size() * sizeof(T));
  std::memcpy(out.data() + at, values.data(), values.size() * sizeof(T));
}

json camera_json(const pipeline::GpuScene& gs, const pipeline::PipelineConfig& config) {
  const scene::Camera cam = pipeline::frame_camera(gs, config);
  const glm::mat4 to_world = glm::inverse(glm::lookAt(cam.position, cam.target, cam.up));
  json rows = json::array();
  for (int r = 0; r < 4; ++r) {
    rows.push_back({to_world[0][r], to_world[1][r], to_world[2][r], to_world[3][r]});
  }
  const bool ortho = cam.projection == scene::Projection::kOrthographic;
  return {{"projection", ortho ? "orthographic" : "perspective"},
          {"camera_to_world", rows},
          {"yfov_radians", cam.yfov_radians},
          {"ymag", cam.ymag},
          {"znear", cam.znear},
          {"zfar", cam.zfar}};
}

json light_json(const scene::DirectionalLight& light) {
  // skinsim's light "radiance" L lights a Lambert surface of albedo a to a L (N.L): the
  // irradiance is pi L, which is a Cycles sun lamp's strength (W/m^2).
  return {{"direction", vec(glm::normalize(light.direction))},
          {"radiance", vec(light.radiance)},
          {"sun_strength_scale", std::numbers::pi_v<float>},
          {"angular_diameter_radians", 2.0f * kLightRadiusRad}};
}

json material_json(const scene::Scene& sc, const scene::Material& m,
                   const pipeline::PipelineConfig& config, json& textures,
                   const std::filesystem::path& dir) {
  json j{{"name", m.name},
         {"base_color_factor",
          {m.base_color_factor.r, m.base_color_factor.g, m.base_color_factor.b,
           m.base_color_factor.a}},
         {"base_color_texture", nullptr},
         {"base_color_srgb", true},
         {"reflectivity", m.reflectivity}};
  if (m.base_color_texture >= 0) {
    const scene::Image& image = sc.images.at(static_cast<std::size_t>(m.base_color_texture));
    const std::string name = "textures/image" + std::to_string(m.base_color_texture) + ".png";
    if (!textures.contains(name)) {
      std::vector<std::uint8_t> bytes(image.texels.size() * 4);
      unorm8_nearest(&image.texels.data()->x, bytes.size(), bytes.data(), nullptr);
      image::write_png_u8(dir / name, image.width, image.height, 4, bytes);
      textures[name] = image.name;
    }
    j["base_color_texture"] = name;
    j["base_color_srgb"] = image.srgb;
  }
  const bake::BrdfLutParams spec = pipeline::brdf_lut_params(config);
  const pipeline::shaders::EyeFS::Uniforms eye;
  switch (m.kind) {
    case scene::MaterialKind::kSkin: {
      j["kind"] = "skin";
      const glm::vec3 radius_mm = subsurface_radius_mm(config.reference_profile);
      j["subsurface"] = {{"profile", pipeline::reference_profile_name(config.reference_profile)},
                         {"radius_mm", vec(radius_mm)},
                         {"radius", vec(radius_mm * sc.units_per_mm)},
                         {"ior", bake::jensen_skin1().eta}};
      // Kelemen/Szirmay-Kalos lobes as Beckmann glossy lobes: Cycles' roughness is
      // sqrt(Beckmann m); the lobe's colour is rho_s x weight (x reflectivity x Fresnel).
      j["ior"] = ior_from_f0(spec.f0);
      j["specular_lobes"] = json::array();
      for (const auto& [m_rough, weight] :
           {std::pair{spec.m1, spec.weight1}, std::pair{spec.m2, spec.weight2}}) {
        j["specular_lobes"].push_back({{"beckmann_m", m_rough},
                                       {"blender_roughness", std::sqrt(m_rough)},
                                       {"scale", spec.rho_s * weight}});
      }
      break;
    }
    case scene::MaterialKind::kEye:
      j["kind"] = "eye";
      j["ior"] = ior_from_f0(eye.cornea_f0);
      // The eye shader's Blinn-Phong highlight (N.H)^n as the Beckmann lobe of the same
      // width, m = sqrt(2 / (n + 2)) (Walter et al. 2007).
      j["cornea"] = {
          {"blender_roughness", std::sqrt(std::sqrt(2.0f / (eye.highlight_power + 2.0f)))},
          {"scale", 1.0f}};
      break;
    case scene::MaterialKind::kOther:
      j["kind"] = "other";
      break;
  }
  return j;
}

}  // namespace

glm::vec3 mean_exit_distance_mm(pipeline::ReferenceProfile profile) {
  if (profile == pipeline::ReferenceProfile::kDipole) {
    // The mean of r under the profile: the integral of 1 - CDF(r) (midpoint rule, out to where
    // every channel has left).
    const bake::DipoleTerms t = bake::dipole_terms(bake::jensen_skin1());
    constexpr float kStepMm = 0.005f, kFarMm = 100.0f;
    glm::dvec3 sum(0.0);
    for (float r = 0.5f * kStepMm; r < kFarMm; r += kStepMm) {
      sum += glm::dvec3(glm::vec3(1.0f) - bake::dipole_cdf(t, r)) * static_cast<double>(kStepMm);
    }
    return glm::vec3(sum);
  }
  // A 2D Gaussian of variance v leaves at a mean distance sqrt(pi v / 2) (Rayleigh).
  glm::vec3 sum(0.0f), weight(0.0f);
  for (const bake::GaussianTerm& g : bake::skin_gaussians()) {
    sum += g.weight * std::sqrt(std::numbers::pi_v<float> * g.variance_mm2 / 2.0f);
    weight += g.weight;
  }
  return sum / weight;
}

glm::vec3 subsurface_radius_mm(pipeline::ReferenceProfile profile) {
  const bake::DipoleTerms t = bake::dipole_terms(bake::jensen_skin1());
  const glm::vec3 dipole = 1.0f / t.sigma_tr;
  if (profile == pipeline::ReferenceProfile::kDipole) return dipole;
  return dipole * mean_exit_distance_mm(profile) /
         mean_exit_distance_mm(pipeline::ReferenceProfile::kDipole);
}

nlohmann::json write_truth_scene(const pipeline::GpuScene& gs,
                                 const pipeline::PipelineConfig& config,
                                 const TruthSettings& settings, const std::filesystem::path& dir) {
  const scene::Scene& sc = gs.scene();
  std::filesystem::create_directories(dir / "textures");
  json d{{"source", sc.source},
         {"width", config.width},
         {"height", config.height},
         {"units_per_mm", sc.units_per_mm},
         {"meshes_file", "meshes.bin"},
         {"render", {{"samples", settings.samples}, {"max_bounces", settings.max_bounces}}},
         {"camera", camera_json(gs, config)}};

  const pipeline::FrameLighting lighting = pipeline::frame_lighting(gs, config);
  d["lights"] = json::array({light_json(lighting.key)});
  if (lighting.has_back()) d["lights"].push_back(light_json(lighting.back));
  // The reference's ambient: constant irradiance added unoccluded to every surface, which a
  // uniform environment of that radiance gives an unoccluded Lambert surface.
  d["world"] = {{"kind", "constant"}, {"radiance", vec(lighting.ambient)}};

  json textures = json::object();
  d["materials"] = json::array();
  for (const scene::Material& m : sc.materials) {
    d["materials"].push_back(material_json(sc, m, config, textures, dir));
  }
  if (sc.materials.empty()) {
    scene::Material fallback;
    fallback.name = "default";
    d["materials"].push_back(material_json(sc, fallback, config, textures, dir));
  }

  std::string bin;
  d["meshes"] = json::array();
  for (const pipeline::GpuMesh& gm : gs.meshes()) {
    const scene::Mesh& mesh = *gm.mesh;
    const std::size_t n = mesh.positions.size();
    json m{{"name", mesh.name.empty() ? "mesh" + std::to_string(d["meshes"].size()) : mesh.name},
           {"material", gm.material},
           {"vertex_count", n},
           {"triangle_count", mesh.triangle_count()},
           // The reference's back light stands 30 cm behind the head, before any backdrop,
           // which therefore shadows nothing; Cycles 3.4 has no light linking, so meshes that
           // are neither skin nor eye cast no shadows at all (docs/validation.md).
           {"casts_shadow", gs.materials()[gm.material].kind != scene::MaterialKind::kOther}};
    m["positions"] = bin.size();
    append(bin, mesh.positions);
    m["normals"] = bin.size();
    append(bin,
           mesh.normals.size() == n ? mesh.normals : std::vector<glm::vec3>(n, glm::vec3(0.0f)));
    m["uvs"] = bin.size();
    append(bin, mesh.uvs.size() == n ? mesh.uvs : std::vector<glm::vec2>(n, glm::vec2(0.0f)));
    m["indices"] = bin.size();
    append(bin, mesh.indices);
    d["meshes"].push_back(m);
  }
  io::write_file_atomically((dir / "meshes.bin").string(), bin);
  io::write_file_atomically((dir / "scene.json").string(), d.dump(2) + "\n");
  return d;
}

}  // namespace skinsim::driver
