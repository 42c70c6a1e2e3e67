// Builds small glTF files for the loader tests: one binary buffer plus JSON, written as
// .gltf (+ external .bin) or .glb into a fresh temporary directory. Tests then break
// single fields to produce each kind of malformed input.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace skinsim::scene::testing {

// A 2x1 RGBA PNG: (255, 0, 0, 255), (0, 128, 255, 64).
extern const std::vector<std::uint8_t> kTwoPixelPng;

class GltfFixture {
 public:
  // A temp directory unique to `test_name`.
  explicit GltfFixture(const std::string& test_name);
  ~GltfFixture();  // removes its directory
  GltfFixture(const GltfFixture&) = delete;
  GltfFixture& operator=(const GltfFixture&) = delete;

  // Appends raw bytes (4-byte aligned) as a new bufferView; returns its index.
  int add_view(const void* data, std::size_t bytes);
  // Appends an accessor over a new bufferView holding `values`; returns its index.
  int add_floats(const std::vector<float>& values, const std::string& type);
  int add_indices(const std::vector<std::uint16_t>& values);

  // One triangle (or quad as 2 triangles) mesh in a node in scene 0. Returns the mesh index.
  // Positions in the z = 0 plane facing +Z, UVs with v down.
  int add_quad_mesh(bool with_normals, bool with_uvs);
  // kTwoPixelPng embedded as the only image and texture; returns the texture's index (0).
  int add_png_texture();

  nlohmann::json& json() { return json_; }
  std::vector<std::uint8_t>& bin() { return bin_; }

  // Writes <name>.gltf and <name>.bin (buffers[0].uri = "<name>.bin"); returns the path.
  std::string write_gltf(const std::string& name);
  // Writes <name>.glb with the buffer in its BIN chunk; returns the path.
  std::string write_glb(const std::string& name);
  // Writes the text as <name> verbatim; returns the path.
  std::string write_raw(const std::string& name, const std::string& bytes);

  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
  nlohmann::json json_;
  std::vector<std::uint8_t> bin_;
};

}  // namespace skinsim::scene::testing
