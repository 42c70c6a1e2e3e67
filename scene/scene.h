// The renderer-independent description of what is drawn: meshes in world space, materials,
// decoded images, camera, lights and the environment. Loaded from glTF (gltf_loader.h) or
// generated (procedural_head.h); consumed by pipeline/, which turns it into GPU draws.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

namespace skinsim::scene {

// A decoded image, RGBA, values exactly as stored in the file (sRGB-encoded colour stays
// encoded; `srgb` says how to read it). Row 0 is the top row, as in glTF.
struct Image {
  std::string name;
  int width = 0;
  int height = 0;
  bool srgb = false;
  std::vector<glm::vec4> texels;  // width * height, row-major
};

// What a material is for the skin pipelines. Decided by classify_materials() below.
enum class MaterialKind { kSkin, kEye, kOther };

struct Material {
  std::string name;
  MaterialKind kind = MaterialKind::kOther;
  glm::vec4 base_color_factor{1.0f};
  int base_color_texture = -1;  // index into Scene::images, -1 = none (use the factor)
  int normal_texture = -1;      // tangent-space normal map, -1 = flat
  float normal_scale = 1.0f;
  float metallic_factor = 0.0f;
  float roughness_factor = 1.0f;
  int metallic_roughness_texture = -1;
  // Specular reflectivity in [0,1] (the skin pipeline's "reflectivity map" channel when the
  // base colour texture has no alpha-encoded reflectivity).
  float reflectivity = 1.0f;
  // glTF `extras.skinsim.kind` ("skin", "eye", "other") if present, else empty.
  std::string extras_kind;
};

// Triangle list in world space (node transforms already applied).
struct Mesh {
  std::string name;
  int material = -1;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;      // unit length
  std::vector<glm::vec2> uvs;          // TEXCOORD_0, (0,0) = top-left of the image
  std::vector<glm::vec4> tangents;     // xyz unit tangent, w = bitangent sign (MikkTSpace)
  std::vector<std::uint32_t> indices;  // 3 per triangle
  std::size_t triangle_count() const { return indices.size() / 3; }
};

enum class Projection { kPerspective, kOrthographic };

struct Camera {
  glm::vec3 position{0.0f, 0.0f, 1.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  Projection projection = Projection::kPerspective;
  float yfov_radians = 0.6f;  // perspective: vertical field of view
  // Orthographic: half the view volume's height (glTF ymag). The width follows the render
  // aspect (glTF: the viewport's aspect wins over xmag / ymag).
  float ymag = 1.0f;
  float znear = 0.01f;
  float zfar = 100.0f;
};

struct DirectionalLight {
  glm::vec3 direction{0.0f, 0.0f, 1.0f};  // unit vector from the surface towards the light
  glm::vec3 radiance{1.0f};               // linear RGB
};

// Linear-radiance cube map, faces in the order +X, -X, +Y, -Y, +Z, -Z (OpenGL convention).
struct CubeMap {
  int size = 0;
  std::array<std::vector<glm::vec4>, 6> faces;
};

// A head found in the skin's geometry by measure_head() (head_measure.h), +Y up, the face
// looking along +Z. `box` is the skin between the chin and the crown.
struct HeadLandmarks {
  glm::vec3 crown{0.0f};     // highest skin point
  glm::vec3 nose_tip{0.0f};  // most forward point of the face
  glm::vec3 chin{0.0f};      // menton on the front profile (see head_measure.h)
  glm::vec3 box_min{0.0f}, box_max{0.0f};
  float height() const { return crown.y - chin.y; }  // crown to chin, scene units
  glm::vec3 centre() const { return 0.5f * (box_min + box_max); }
};

// Where Scene::units_per_mm came from.
enum class UnitsSource {
  kGiven,       // --units-per-mm (LoadOptions::units_per_mm), or the built-in head's metres
  kFile,        // glTF's metres, which give a head of plausible size
  kHeadHeight,  // the measured head height taken as a typical head's (kTypicalHeadMm)
  kBoxHeight,   // no head measured: the skin's bounding-box height taken as a head's
};

struct Scene {
  std::string source;  // file path, or "builtin:default-head"
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Image> images;
  Camera camera;
  DirectionalLight key_light;  // casts the shadows
  // A rim light from behind (transmission through the ears); radiance 0 = none.
  DirectionalLight back_light{{0.0f, 0.0f, -1.0f}, glm::vec3(0.0f)};
  glm::vec3 ambient{0.05f};
  CubeMap environment;
  // World units per millimetre: diffusion profiles are in mm (skin-techniques.md section 4).
  float units_per_mm = 0.001f;  // glTF is in metres
  UnitsSource units_source = UnitsSource::kGiven;
  // The head the camera frames and orbits; absent when the skin's shape did not show one.
  std::optional<HeadLandmarks> head;
};

// Decides Material::kind. Rule, first match wins:
//   1. a material whose name is in `skin_override` (the CLI's --skin-materials) is skin;
//      the special entry "all" makes every material skin;
//   2. glTF extras {"skinsim": {"kind": "skin"|"eye"|"other"}};
//   3. a name containing "skin" (any case) is skin; containing "eye" is eye;
//   4. otherwise other.
// The glTF loader then takes a scan's only material as skin when its shape is a head
// (sole_skin.h).
void classify_materials(Scene& scene, const std::vector<std::string>& skin_override);

}  // namespace skinsim::scene
