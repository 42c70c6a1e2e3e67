#include "scene/gltf_loader.h"

#include <fmt/format.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "scene/bounds.h"
#include "scene/camera_framing.h"
#include "scene/error.h"
#include "scene/gltf_input.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_nodes.h"
#include "scene/gltf_primitive.h"
#include "scene/load_warnings.h"
#include "scene/scene_scale.h"
#include "scene/skin_albedo.h"
#include "scene/sole_skin.h"
#include "scene/studio_lighting.h"
#include "scene/validate.h"

namespace skinsim::scene {
namespace {

using Warn = std::function<void(const std::string&)>;

// Extensions this loader understands well enough that a file may require them.
void check_required_extensions(const tinygltf::Model& model, const std::string& path) {
  static const std::set<std::string> kSupported = {"KHR_lights_punctual"};
  for (const std::string& ext : model.extensionsRequired) {
    if (!kSupported.count(ext)) {
      throw SceneError(fmt::format(
          "{}: extensionsRequired lists {}, which skinsim does not support", path, ext));
    }
  }
}

int pick_scene(const tinygltf::Model& model, const std::string& path) {
  if (model.scenes.empty()) throw SceneError(fmt::format("{}: the file defines no scene", path));
  const int s = model.defaultScene < 0 ? 0 : model.defaultScene;
  if (static_cast<std::size_t>(s) >= model.scenes.size()) {
    throw SceneError(
        fmt::format("{}: scene {} out of range ({} scenes)", path, s, model.scenes.size()));
  }
  return s;
}

// A glTF camera's projection (spec 5.12, 5.13), validated; zfar 0 = absent (perspective only).
void apply_projection(const tinygltf::Camera& c, int index, const std::string& path, Camera& cam,
                      double& zfar) {
  if (c.type == "perspective") {
    const auto& p = c.perspective;
    if (!(p.yfov > 0.0 && p.yfov < std::numbers::pi) || !(p.znear > 0.0) ||
        (p.zfar != 0.0 && !(p.zfar > p.znear))) {
      throw SceneError(
          fmt::format("{}: cameras[{}].perspective: need 0 < yfov < pi, znear > 0, "
                      "zfar > znear (or absent)",
                      path, index));
    }
    cam.projection = Projection::kPerspective;
    cam.yfov_radians = static_cast<float>(p.yfov);
    cam.znear = static_cast<float>(p.znear);
    zfar = p.zfar;
    return;
  }
  if (c.type == "orthographic") {
    const auto& o = c.orthographic;
    // xmag is checked but not used: the render aspect sets the width (see Camera::ymag).
    if (!(o.xmag > 0.0 && std::isfinite(o.xmag)) || !(o.ymag > 0.0 && std::isfinite(o.ymag)) ||
        !(o.znear >= 0.0) || !(o.zfar > o.znear && std::isfinite(o.zfar))) {
      throw SceneError(
          fmt::format("{}: cameras[{}].orthographic: need xmag > 0, ymag > 0, znear >= 0, "
                      "zfar > znear",
                      path, index));
    }
    cam.projection = Projection::kOrthographic;
    cam.ymag = static_cast<float>(o.ymag);
    cam.znear = static_cast<float>(o.znear);
    zfar = o.zfar;
    return;
  }
  throw SceneError(fmt::format("{}: cameras[{}].type '{}': need 'perspective' or 'orthographic'",
                               path, index, c.type));
}

// The camera of the first node (pre-order) that has one.
bool apply_file_camera(const tinygltf::Model& model, const std::vector<gltf::PlacedNode>& nodes,
                       const Bounds& bounds, const std::string& path, Camera& cam) {
  for (const auto& placed : nodes) {
    const int index = model.nodes[static_cast<std::size_t>(placed.node)].camera;
    if (index < 0) continue;
    if (static_cast<std::size_t>(index) >= model.cameras.size()) {
      throw SceneError(fmt::format("{}: nodes[{}].camera {} out of range ({} cameras)", path,
                                   placed.node, index, model.cameras.size()));
    }
    double zfar = 0.0;
    apply_projection(model.cameras[static_cast<std::size_t>(index)], index, path, cam, zfar);
    const glm::mat4& w = placed.world;
    cam.position = glm::vec3(w[3]);
    const glm::vec3 forward = glm::normalize(glm::vec3(w * glm::vec4(0, 0, -1, 0)));
    cam.up = glm::normalize(glm::vec3(w * glm::vec4(0, 1, 0, 0)));
    const float to_center = glm::dot(bounds.center() - cam.position, forward);
    cam.target = cam.position + forward * (to_center > 0.0f ? to_center : 1.0f);
    // zfar absent means an infinite projection; use a far plane well past the scene.
    const float reach = glm::length(bounds.center() - cam.position) + glm::length(bounds.extent());
    cam.zfar = zfar > 0.0 ? static_cast<float>(zfar) : std::max(reach * 2.0f, cam.znear * 2.0f);
    return true;
  }
  return false;
}

// The first KHR_lights_punctual directional light (spec: it shines along the node's -Z).
bool apply_file_light(const tinygltf::Model& model, const std::vector<gltf::PlacedNode>& nodes,
                      const std::string& path, const Warn& warn, DirectionalLight& light) {
  bool found = false;
  for (const auto& placed : nodes) {
    const auto& ext = model.nodes[static_cast<std::size_t>(placed.node)].extensions;
    auto it = ext.find("KHR_lights_punctual");
    if (it == ext.end() || !it->second.IsObject() || !it->second.Has("light")) continue;
    const tinygltf::Value& v = it->second.Get("light");
    const int index = v.IsInt() ? v.Get<int>() : -1;
    if (index < 0 || static_cast<std::size_t>(index) >= model.lights.size()) {
      throw SceneError(
          fmt::format("{}: nodes[{}].extensions.KHR_lights_punctual.light out of "
                      "range ({} lights)",
                      path, placed.node, model.lights.size()));
    }
    const tinygltf::Light& l = model.lights[static_cast<std::size_t>(index)];
    if (l.type != "directional" || found) {
      warn(fmt::format("{}: lights[{}] ({}) ignored: skinsim uses one directional key light", path,
                       index, l.type));
      continue;
    }
    glm::vec3 color(1.0f);
    if (l.color.size() == 3) color = glm::vec3(l.color[0], l.color[1], l.color[2]);
    const glm::vec3 shine = glm::vec3(placed.world * glm::vec4(0, 0, -1, 0));
    light.direction = glm::normalize(-shine);
    // Intensity is taken as a plain multiplier of linear RGB (the spec's lux have no
    // meaning without an exposure, which skinsim does not model).
    light.radiance = color * static_cast<float>(l.intensity);
    if (!std::isfinite(light.direction.x) ||
        !std::isfinite(light.radiance.x + light.radiance.y + light.radiance.z)) {
      throw SceneError(
          fmt::format("{}: lights[{}]: direction or colour is not finite", path, index));
    }
    found = true;
  }
  return found;
}

}  // namespace

PosedGltf::PosedGltf(const std::string& path, const LoadOptions& opts) : path_(path), opts_(opts) {
  const Warn warn =
      opts_.warn ? opts_.warn
                 : Warn([](const std::string& msg) { fmt::print(stderr, "warning: {}\n", msg); });
  opts_.warn = [this, warn](const std::string& msg) {
    if (warned_.insert(msg).second) warn(msg);
  };
  if (!(opts.aspect > 0.0f) ||
      !(opts.auto_camera_yfov_radians > 0.0f && opts.auto_camera_yfov_radians < 3.0f)) {
    throw SceneError(fmt::format(
        "{}: LoadOptions: aspect must be > 0 and auto_camera_yfov_radians in (0, 3)", path));
  }
  model_ = std::make_unique<tinygltf::Model>(gltf::parse_gltf_file(path));
  check_required_extensions(*model_, path);
  scene_index_ = pick_scene(*model_, path);
  gltf::convert_materials(*model_, path, materials_, opts_.warn);
}

PosedGltf::~PosedGltf() = default;

Scene load_gltf(const std::string& path, const LoadOptions& opts) {
  return PosedGltf(path, opts).pose(nullptr, 0.0);
}

Scene PosedGltf::pose(const NodeAnimation* animation, double time_s) {
  const tinygltf::Model& model = *model_;
  const std::string& path = path_;
  const LoadOptions& opts = opts_;
  const Warn& warn = opts_.warn;
  const int scene_index = scene_index_;
  const std::vector<gltf::PlacedNode> nodes =
      gltf::flatten_scene(model, scene_index, path, animation, time_s);

  Scene scene;
  scene.source = path;
  scene.materials = materials_.materials;
  scene.images = materials_.images;
  int default_material = -1;  // glTF's default material (spec 3.9.6), added on first use
  for (const auto& placed : nodes) {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(placed.node)];
    const int mesh = node.mesh;
    if (mesh < 0) continue;
    if (node.skin >= 0) {
      warn(
          fmt::format("{}: nodes[{}] is skinned (skins[{}]), and skinsim does not play skins: "
                      "its mesh is drawn in its bind pose (docs/sequences.md)",
                      path, placed.node, node.skin));
    }
    if (static_cast<std::size_t>(mesh) >= model.meshes.size()) {
      throw SceneError(fmt::format("{}: nodes[{}].mesh {} out of range ({} meshes)", path,
                                   placed.node, mesh, model.meshes.size()));
    }
    const auto& prims = model.meshes[static_cast<std::size_t>(mesh)].primitives;
    for (std::size_t p = 0; p < prims.size(); ++p) {
      int material = prims[p].material;
      if (material >= static_cast<int>(model.materials.size()) || material < -1) {
        throw SceneError(
            fmt::format("{}: meshes[{}].primitives[{}].material {} out of range ({} "
                        "materials)",
                        path, mesh, p, material, model.materials.size()));
      }
      if (material < 0) {
        if (default_material < 0) {
          Material d;
          d.name = "default";
          d.metallic_factor = 1.0f;
          scene.materials.push_back(d);
          default_material = static_cast<int>(scene.materials.size()) - 1;
        }
        material = default_material;
      }
      if (auto m = gltf::convert_primitive(model, mesh, static_cast<int>(p), placed.world,
                                           placed.weights, material, path, warn)) {
        scene.meshes.push_back(std::move(*m));
      }
    }
  }
  if (scene.meshes.empty()) {
    throw SceneError(fmt::format("{}: scenes[{}] contains no triangles", path, scene_index));
  }

  classify_materials(scene, opts.skin_materials);
  if (opts.skin_materials.empty()) {
    if (const std::string note = take_sole_material_as_skin(scene); !note.empty()) {
      warn(fmt::format("{}: {}", path, note));
    }
  }
  size_scene(scene, opts.units_per_mm, warn);
  const Bounds bounds = scene_bounds(scene);
  if (!apply_file_camera(model, nodes, bounds, path, scene.camera)) {
    scene.camera = scene.head
                       ? frame_face(*scene.head, opts.auto_camera_yfov_radians, opts.aspect)
                       : frame_front(bounds, opts.auto_camera_yfov_radians, opts.aspect, 0.05f);
  }
  scene.key_light = default_key_light();
  scene.back_light = default_back_light(scene.key_light);
  scene.ambient = default_ambient();
  apply_file_light(model, nodes, path, warn, scene.key_light);
  scene.environment = make_studio_environment(opts.environment_size, scene.key_light);
  if (!opts.skin_albedo.empty()) apply_skin_albedo(scene, opts.skin_albedo);
  validate_scene(scene);
  warn_untextured_materials(scene, warn, opts.skin_albedo.empty());
  return scene;
}

}  // namespace skinsim::scene
