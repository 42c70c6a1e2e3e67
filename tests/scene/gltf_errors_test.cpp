// Every kind of malformed glTF input must raise SceneError whose message starts with the
// file path and names the problem, never crash or hang.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "scene/error.h"
#include "scene/gltf_loader.h"
#include "tests/scene/gltf_fixture.h"

namespace skinsim::scene {
namespace {

using testing::GltfFixture;

LoadOptions quiet() {
  LoadOptions o;
  o.warn = [](const std::string&) {};
  o.environment_size = 2;
  return o;
}

// Loads `path` and checks that it fails with a message that starts with the path and
// contains `expected`.
void expect_error(const std::string& path, const std::string& expected) {
  try {
    load_gltf(path, quiet());
    FAIL() << "no error for " << path;
  } catch (const SceneError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path, 0), 0u) << msg;
    EXPECT_NE(msg.find(expected), std::string::npos) << "message: " << msg;
  }
}

TEST(GltfErrors, MissingFile) {
  GltfFixture f("missing_file");
  expect_error((f.dir() / "nope.glb").string(), "file not found");
}

TEST(GltfErrors, WrongExtension) {
  GltfFixture f("wrong_ext");
  expect_error(f.write_raw("head.obj", "v 0 0 0\n"), ".gltf or .glb");
}

TEST(GltfErrors, InvalidJson) {
  GltfFixture f("bad_json");
  expect_error(f.write_raw("bad.gltf", "{\"asset\": {\"version\": \"2.0\"}, "), "cannot parse");
}

TEST(GltfErrors, TruncatedGlb) {
  GltfFixture f("truncated_glb");
  f.add_quad_mesh(true, true);
  const std::string full = f.write_glb("full");
  std::ifstream in(full, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  for (std::size_t keep :
       {std::size_t{0}, std::size_t{7}, std::size_t{19}, bytes.size() / 2, bytes.size() - 4}) {
    expect_error(f.write_raw("cut" + std::to_string(keep) + ".glb", bytes.substr(0, keep)),
                 "cannot parse");
  }
}

TEST(GltfErrors, MissingBufferFile) {
  GltfFixture f("missing_buffer");
  f.add_quad_mesh(true, true);
  const std::string path = f.write_gltf("scene");
  std::filesystem::remove(f.dir() / "scene.bin");
  expect_error(path, "buffers[0].uri 'scene.bin'");
}

TEST(GltfErrors, ShortBuffer) {
  GltfFixture f("short_buffer");
  f.add_quad_mesh(true, true);
  const std::string path = f.write_gltf("scene");
  std::filesystem::resize_file(f.dir() / "scene.bin", 16);
  // The buffer file is shorter than buffers[0].byteLength.
  try {
    load_gltf(path, quiet());
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path, 0), 0u) << e.what();
  }
}

TEST(GltfErrors, BufferViewBeyondBuffer) {
  GltfFixture f("view_beyond_buffer");
  f.add_quad_mesh(true, true);
  f.json()["bufferViews"][0]["byteLength"] = 4096;
  expect_error(f.write_glb("scene"), "bufferViews[0]");
}

TEST(GltfErrors, AccessorBeyondBufferView) {
  GltfFixture f("accessor_beyond_view");
  f.add_quad_mesh(true, true);
  f.json()["accessors"][0]["count"] = 5;  // POSITION: 4 vertices stored
  expect_error(f.write_glb("scene"), "do not fit bufferViews[0]");
}

TEST(GltfErrors, AccessorOffsetBeyondBufferView) {
  GltfFixture f("accessor_offset");
  f.add_quad_mesh(true, true);
  f.json()["accessors"][0]["byteOffset"] = 40;
  expect_error(f.write_glb("scene"), "byteOffset 40");
}

TEST(GltfErrors, AccessorIndexOutOfRange) {
  GltfFixture f("accessor_index");
  f.add_quad_mesh(true, true);
  f.json()["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 99;
  expect_error(f.write_glb("scene"), "attributes.NORMAL");
}

TEST(GltfErrors, AttributeCountMismatch) {
  GltfFixture f("count_mismatch");
  f.add_quad_mesh(true, true);
  f.json()["accessors"][1]["count"] = 3;  // NORMAL: 3 of 4
  expect_error(f.write_glb("scene"), "POSITION has 4");
}

TEST(GltfErrors, IndexOutOfVertexRange) {
  GltfFixture f("index_range");
  f.add_quad_mesh(true, true);
  const int bad = f.add_indices({0, 1, 7});
  f.json()["meshes"][0]["primitives"][0]["indices"] = bad;
  expect_error(f.write_glb("scene"), "index 7");
}

TEST(GltfErrors, IndexCountNotMultipleOfThree) {
  GltfFixture f("index_count");
  f.add_quad_mesh(true, true);
  f.json()["meshes"][0]["primitives"][0]["indices"] = f.add_indices({0, 1, 2, 3});
  expect_error(f.write_glb("scene"), "not a multiple of 3");
}

TEST(GltfErrors, NanAndInfPositions) {
  for (float bad :
       {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    GltfFixture f(std::isnan(bad) ? "nan_position" : "inf_position");
    const int pos = f.add_floats({0, 0, 0, 1, 0, 0, 0, bad, 0}, "VEC3");
    f.json()["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", pos}}}}}}});
    f.json()["nodes"].push_back({{"mesh", 0}});
    f.json()["scenes"][0]["nodes"].push_back(0);
    expect_error(f.write_glb("scene"), "vertex 2 is not finite");
  }
}

TEST(GltfErrors, WrongComponentType) {
  GltfFixture f("component_type");
  f.add_quad_mesh(true, true);
  f.json()["accessors"][0]["componentType"] = 5123;  // POSITION as UNSIGNED_SHORT
  expect_error(f.write_glb("scene"), "componentType UNSIGNED_SHORT");
}

TEST(GltfErrors, FloatIndices) {
  GltfFixture f("float_indices");
  f.add_quad_mesh(true, true);
  f.json()["meshes"][0]["primitives"][0]["indices"] = f.add_floats({0, 1, 2}, "SCALAR");
  expect_error(f.write_glb("scene"), "index componentType");
}

TEST(GltfErrors, WrongAccessorType) {
  GltfFixture f("accessor_type");
  f.add_quad_mesh(true, true);
  f.json()["accessors"][0]["type"] = "VEC2";
  f.json()["accessors"][0]["count"] = 4;
  expect_error(f.write_glb("scene"), "must have 3 components");
}

TEST(GltfErrors, RequiredUnsupportedExtension) {
  GltfFixture f("required_extension");
  f.add_quad_mesh(true, true);
  f.json()["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  f.json()["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  expect_error(f.write_glb("scene"), "KHR_draco_mesh_compression");
}

TEST(GltfErrors, NodeCycle) {
  GltfFixture f("node_cycle");
  f.add_quad_mesh(true, true);                       // node 0
  f.json()["nodes"].push_back({{"children", {0}}});  // node 1 -> 0
  f.json()["nodes"][0]["children"] = {1};            // node 0 -> 1
  expect_error(f.write_glb("scene"), "cycle");
}

TEST(GltfErrors, NodeIsItsOwnChild) {
  GltfFixture f("self_child");
  f.add_quad_mesh(true, true);
  f.json()["nodes"][0]["children"] = {0};
  expect_error(f.write_glb("scene"), "cycle");
}

TEST(GltfErrors, NodeWithTwoParents) {
  GltfFixture f("two_parents");
  f.add_quad_mesh(true, true);  // node 0 (a root)
  f.json()["nodes"].push_back({{"children", {0}}});
  f.json()["scenes"][0]["nodes"].push_back(1);
  expect_error(f.write_glb("scene"), "two parents");
}

TEST(GltfErrors, ChildIndexOutOfRange) {
  GltfFixture f("child_range");
  f.add_quad_mesh(true, true);
  f.json()["nodes"][0]["children"] = {42};
  expect_error(f.write_glb("scene"), "node index 42");
}

TEST(GltfErrors, BadNodeTransform) {
  GltfFixture f("bad_transform");
  f.add_quad_mesh(true, true);
  f.json()["nodes"][0]["rotation"] = {0, 0, 0, 0};
  expect_error(f.write_glb("scene"), "zero quaternion");
}

TEST(GltfErrors, NoScene) {
  GltfFixture f("no_scene");
  f.add_quad_mesh(true, true);
  f.json().erase("scene");
  f.json()["scenes"] = nlohmann::json::array();
  expect_error(f.write_glb("scene"), "no scene");
}

TEST(GltfErrors, EmptyScene) {
  GltfFixture f("empty_scene");
  f.add_quad_mesh(true, true);
  f.json()["scenes"][0]["nodes"] = nlohmann::json::array();
  expect_error(f.write_glb("scene"), "no triangles");
}

TEST(GltfErrors, OnlyPointsIsEmpty) {
  GltfFixture f("points_only");
  f.add_quad_mesh(true, true);
  f.json()["meshes"][0]["primitives"][0]["mode"] = 0;  // POINTS
  expect_error(f.write_glb("scene"), "no triangles");
}

TEST(GltfErrors, MissingPosition) {
  GltfFixture f("no_position");
  f.add_quad_mesh(true, true);
  f.json()["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
  expect_error(f.write_glb("scene"), "no POSITION");
}

TEST(GltfErrors, BadMaterialKind) {
  GltfFixture f("material_kind");
  f.add_quad_mesh(true, true);
  f.json()["materials"] = {{{"name", "face"}, {"extras", {{"skinsim", {{"kind", "hair"}}}}}}};
  f.json()["meshes"][0]["primitives"][0]["material"] = 0;
  expect_error(f.write_glb("scene"), "materials[0].extras.skinsim.kind");
}

TEST(GltfErrors, MaterialIndexOutOfRange) {
  GltfFixture f("material_range");
  f.add_quad_mesh(true, true);
  f.json()["meshes"][0]["primitives"][0]["material"] = 3;
  expect_error(f.write_glb("scene"), "material 3 out of range");
}

TEST(GltfErrors, ImageBufferViewBeyondBuffer) {
  GltfFixture f("image_view");
  f.add_quad_mesh(true, true);
  const std::uint8_t junk[8] = {0x89, 'P', 'N', 'G', 0, 0, 0, 0};
  const int view = f.add_view(junk, sizeof(junk));
  f.json()["bufferViews"][view]["byteLength"] = 100000;  // tinygltf would read past the buffer
  f.json()["images"] = {{{"bufferView", view}, {"mimeType", "image/png"}}};
  f.json()["textures"] = {{{"source", 0}}};
  f.json()["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  f.json()["meshes"][0]["primitives"][0]["material"] = 0;
  expect_error(f.write_glb("scene"), "images[0].bufferView");
}

TEST(GltfErrors, UndecodableImage) {
  GltfFixture f("image_garbage");
  f.add_quad_mesh(true, true);
  const std::uint8_t junk[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  const int view = f.add_view(junk, sizeof(junk));
  f.json()["images"] = {{{"bufferView", view}, {"mimeType", "image/png"}}};
  f.json()["textures"] = {{{"source", 0}}};
  f.json()["materials"] = {{{"normalTexture", {{"index", 0}}}}};
  f.json()["meshes"][0]["primitives"][0]["material"] = 0;
  expect_error(f.write_glb("scene"), "images[0]");
}

TEST(GltfErrors, TextureIndexOutOfRange) {
  GltfFixture f("texture_range");
  f.add_quad_mesh(true, true);
  f.json()["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 5}}}}}}};
  f.json()["meshes"][0]["primitives"][0]["material"] = 0;
  expect_error(f.write_glb("scene"), "texture index 5");
}

}  // namespace
}  // namespace skinsim::scene

namespace skinsim::scene {
namespace {

// Corrupts a valid .glb one byte at a time (deterministic positions and values): every
// load either succeeds or throws SceneError; nothing else escapes and nothing crashes.
TEST(GltfErrors, SingleByteCorruptionNeverCrashes) {
  GltfFixture f("corruption");
  f.add_quad_mesh(true, true);
  f.json()["materials"] = {{{"name", "skin"}, {"normalTexture", {{"index", 0}}}}};
  f.json()["meshes"][0]["primitives"][0]["material"] = 0;
  const std::uint8_t png[] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
  f.json()["images"] = {{{"bufferView", f.add_view(png, sizeof(png))}, {"mimeType", "image/png"}}};
  f.json()["textures"] = {{{"source", 0}}};
  std::ifstream in(f.write_glb("valid"), std::ios::binary);
  const std::string valid((std::istreambuf_iterator<char>(in)), {});
  std::uint32_t state = 12345u;
  for (int trial = 0; trial < 300; ++trial) {
    state = state * 1664525u + 1013904223u;  // LCG: fixed sequence
    std::string bytes = valid;
    const std::size_t at = (state >> 8) % bytes.size();
    bytes[at] = static_cast<char>(bytes[at] ^ (1 + (state >> 24) % 255));
    const std::string path = f.write_raw("corrupt.glb", bytes);
    try {
      load_gltf(path, quiet());
    } catch (const SceneError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path, 0), 0u) << e.what();
    }
  }
}

struct BadCamera {
  const char* name;
  nlohmann::json camera;
  const char* expected;
};

class GltfCameraErrors : public ::testing::TestWithParam<BadCamera> {};

TEST_P(GltfCameraErrors, NamesTheCameraField) {
  testing::GltfFixture f(std::string("camera_") + GetParam().name);
  f.add_quad_mesh(true, true);
  f.json()["cameras"] = {GetParam().camera};
  f.json()["nodes"].push_back({{"camera", 0}});
  f.json()["scenes"][0]["nodes"].push_back(1);
  expect_error(f.write_gltf("scene"), GetParam().expected);
}

nlohmann::json ortho(double xmag, double ymag, double znear, double zfar) {
  return {{"type", "orthographic"},
          {"orthographic", {{"xmag", xmag}, {"ymag", ymag}, {"znear", znear}, {"zfar", zfar}}}};
}

INSTANTIATE_TEST_SUITE_P(
    Cases, GltfCameraErrors,
    ::testing::Values(
        BadCamera{"ortho_zero_ymag", ortho(1, 0, 0.1, 10), "cameras[0].orthographic: need"},
        BadCamera{"ortho_negative_xmag", ortho(-1, 1, 0.1, 10), "cameras[0].orthographic: need"},
        BadCamera{"ortho_negative_znear", ortho(1, 1, -0.1, 10), "cameras[0].orthographic: need"},
        BadCamera{"ortho_zfar_before_znear", ortho(1, 1, 2, 1), "cameras[0].orthographic: need"},
        BadCamera{"perspective_zero_yfov",
                  {{"type", "perspective"}, {"perspective", {{"yfov", 0.0}, {"znear", 0.1}}}},
                  "cameras[0].perspective: need"}),
    [](const auto& test) { return std::string(test.param.name); });

}  // namespace
}  // namespace skinsim::scene
