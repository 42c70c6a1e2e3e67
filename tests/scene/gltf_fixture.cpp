#include "tests/scene/gltf_fixture.h"

#include <unistd.h>

#include <cstring>
#include <fstream>

namespace skinsim::scene::testing {

GltfFixture::GltfFixture(const std::string& test_name) {
  // The process id keeps apart fixtures of the same name that CTest runs at once (each
  // instance of a parameterised test is a process of its own).
  dir_ = std::filesystem::temp_directory_path() / "skinsim_scene_tests" /
         (test_name + "." + std::to_string(::getpid()));
  std::filesystem::remove_all(dir_);
  std::filesystem::create_directories(dir_);
  json_ = {{"asset", {{"version", "2.0"}}},
           {"scene", 0},
           {"scenes", {{{"nodes", nlohmann::json::array()}}}},
           {"nodes", nlohmann::json::array()},
           {"meshes", nlohmann::json::array()},
           {"accessors", nlohmann::json::array()},
           {"bufferViews", nlohmann::json::array()},
           {"buffers", nlohmann::json::array({{{"byteLength", 0}}})}};
}

GltfFixture::~GltfFixture() {
  std::error_code ignored;  // best effort: a leftover directory in /tmp harms nothing
  std::filesystem::remove_all(dir_, ignored);
}

int GltfFixture::add_view(const void* data, std::size_t bytes) {
  const std::size_t offset = bin_.size();
  bin_.resize(offset + bytes);
  std::memcpy(bin_.data() + offset, data, bytes);
  while (bin_.size() % 4 != 0) bin_.push_back(0);
  json_["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
  json_["buffers"][0]["byteLength"] = bin_.size();
  return static_cast<int>(json_["bufferViews"].size()) - 1;
}

int GltfFixture::add_floats(const std::vector<float>& values, const std::string& type) {
  const int comps = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : 4;
  const int view = add_view(values.data(), values.size() * sizeof(float));
  json_["accessors"].push_back({{"bufferView", view},
                                {"componentType", 5126},
                                {"count", values.size() / comps},
                                {"type", type}});
  return static_cast<int>(json_["accessors"].size()) - 1;
}

int GltfFixture::add_indices(const std::vector<std::uint16_t>& values) {
  const int view = add_view(values.data(), values.size() * sizeof(std::uint16_t));
  json_["accessors"].push_back({{"bufferView", view},
                                {"componentType", 5123},
                                {"count", values.size()},
                                {"type", "SCALAR"}});
  return static_cast<int>(json_["accessors"].size()) - 1;
}

const std::vector<std::uint8_t> kTwoPixelPng = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44,
    0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0xf4,
    0x22, 0x7f, 0x8a, 0x00, 0x00, 0x00, 0x11, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8,
    0xcf, 0xc0, 0xf0, 0x9f, 0xa1, 0xe1, 0xbf, 0x03, 0x00, 0x10, 0xba, 0x03, 0xbe, 0x47, 0x96,
    0x20, 0xa0, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

int GltfFixture::add_png_texture() {
  const int view = add_view(kTwoPixelPng.data(), kTwoPixelPng.size());
  json_["images"] = {{{"bufferView", view}, {"mimeType", "image/png"}}};
  json_["textures"] = {{{"source", 0}}};
  return 0;
}

int GltfFixture::add_quad_mesh(bool with_normals, bool with_uvs) {
  nlohmann::json attributes;
  attributes["POSITION"] = add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, "VEC3");
  if (with_normals) attributes["NORMAL"] = add_floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3");
  if (with_uvs) attributes["TEXCOORD_0"] = add_floats({0, 1, 1, 1, 0, 0, 1, 0}, "VEC2");
  const int indices = add_indices({0, 1, 2, 2, 1, 3});
  json_["meshes"].push_back({{"primitives", {{{"attributes", attributes}, {"indices", indices}}}}});
  const int mesh = static_cast<int>(json_["meshes"].size()) - 1;
  json_["nodes"].push_back({{"mesh", mesh}});
  json_["scenes"][0]["nodes"].push_back(json_["nodes"].size() - 1);
  return mesh;
}

std::string GltfFixture::write_gltf(const std::string& name) {
  const std::string bin_name = name + ".bin";
  json_["buffers"][0]["uri"] = bin_name;
  {
    std::ofstream bin(dir_ / bin_name, std::ios::binary);
    bin.write(reinterpret_cast<const char*>(bin_.data()),
              static_cast<std::streamsize>(bin_.size()));
  }
  return write_raw(name + ".gltf", json_.dump());
}

std::string GltfFixture::write_glb(const std::string& name) {
  json_["buffers"][0].erase("uri");
  std::string text = json_.dump();
  while (text.size() % 4 != 0) text.push_back(' ');
  const auto u32 = [](std::string& out, std::uint32_t v) {
    out.append(reinterpret_cast<const char*>(&v), 4);  // little-endian host
  };
  std::string glb = "glTF";
  u32(glb, 2);
  u32(glb, static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin_.size()));
  u32(glb, static_cast<std::uint32_t>(text.size()));
  u32(glb, 0x4E4F534A);  // "JSON"
  glb += text;
  u32(glb, static_cast<std::uint32_t>(bin_.size()));
  u32(glb, 0x004E4942);  // "BIN\0"
  glb.append(reinterpret_cast<const char*>(bin_.data()), bin_.size());
  return write_raw(name + ".glb", glb);
}

std::string GltfFixture::write_raw(const std::string& name, const std::string& bytes) {
  const std::filesystem::path path = dir_ / name;
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path.string();
}

}  // namespace skinsim::scene::testing
