#include "scene/gltf_input.h"

#include <fmt/format.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string_view>
#include <vector>

#include "io/json_input.h"
#include "io/read_file.h"
#include "scene/error.h"
#include "scene/gltf_materials.h"
#include "util/fingerprint.h"
#include "util/text.h"

namespace skinsim::scene::gltf {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw SceneError(fmt::format("{}: cannot parse glTF: {}", path, why));
}

std::uint32_t read_u32(const std::string& bytes, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);  // GLB is little-endian, as is every target here
  return v;
}

// The JSON chunk of a GLB (spec 4.4) after checking the header and every chunk length
// against the file, so tinygltf never reads past the end.
std::string_view glb_json_chunk(const std::string& bytes, const std::string& path) {
  constexpr std::uint32_t kMagic = 0x46546C67, kJson = 0x4E4F534A, kBin = 0x004E4942;
  if (bytes.size() < 20)
    fail(path, fmt::format("GLB of {} bytes is shorter than its 20-byte header", bytes.size()));
  if (read_u32(bytes, 0) != kMagic) fail(path, "GLB does not start with the magic 'glTF'");
  if (read_u32(bytes, 4) != 2)
    fail(path, fmt::format("GLB version {} (expected 2)", read_u32(bytes, 4)));
  const std::uint64_t length = read_u32(bytes, 8);
  if (length != bytes.size()) {
    fail(path, fmt::format("GLB header says {} bytes, the file has {}", length, bytes.size()));
  }
  const std::uint64_t json_length = read_u32(bytes, 12);
  if (read_u32(bytes, 16) != kJson) fail(path, "GLB's first chunk is not JSON");
  if (json_length == 0 || 20 + json_length > length) {
    fail(path, fmt::format("GLB JSON chunk length {} does not fit the {}-byte file", json_length,
                           length));
  }
  const std::uint64_t bin_at = 20 + json_length;
  if (bin_at < length) {
    if (length - bin_at < 8) fail(path, "GLB ends inside a chunk header");
    const std::uint64_t bin_length = read_u32(bytes, bin_at);
    if (read_u32(bytes, bin_at + 4) != kBin) fail(path, "GLB's second chunk is not BIN");
    if (bin_length > length - bin_at - 8) {
      fail(path, fmt::format("GLB BIN chunk length {} does not fit the {}-byte file", bin_length,
                             length));
    }
  }
  return std::string_view(bytes).substr(20, json_length);
}

void check_depth(std::string_view json, const std::string& path) {
  if (auto at = io::find_nesting_beyond(json, io::kMaxJsonDepth)) {
    fail(path, fmt::format("JSON nests deeper than {} levels (at JSON byte {}); real glTF files "
                           "nest fewer than 20",
                           io::kMaxJsonDepth, *at));
  }
}

std::string percent_decode(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// The files that every external buffers[i].uri / images[i].uri names, each checked to be a
// regular file of bounded size here, so the message can name the index and URI (tinygltf's
// cannot).
std::vector<fs::path> external_files(std::string_view json_text, const fs::path& dir,
                                     const std::string& path) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(json_text);
  } catch (const nlohmann::json::exception& e) {
    fail(path, fmt::format("invalid JSON: {}", e.what()));
  }
  if (!doc.is_object()) fail(path, "the JSON top level is not an object");
  std::vector<fs::path> files;
  for (const char* array : {"buffers", "images"}) {
    const auto it = doc.find(array);
    if (it == doc.end() || !it->is_array()) continue;
    for (std::size_t i = 0; i < it->size(); ++i) {
      const nlohmann::json& entry = (*it)[i];
      if (!entry.is_object() || !entry.contains("uri") || !entry["uri"].is_string()) continue;
      const std::string uri = entry["uri"].get<std::string>();
      if (uri.rfind("data:", 0) == 0) continue;
      files.push_back(dir / percent_decode(uri));
      try {
        io::require_regular_file(files.back(),
                                 fmt::format("{}: {}[{}].uri '{}' names", path, array, i, uri),
                                 kMaxGltfInputBytes);
      } catch (const io::InputError& e) {
        throw SceneError(e.what());
      }
    }
  }
  return files;
}

// tinygltf's file access, replaced: no wordexp() path expansion, no fopen() that blocks on a
// FIFO, and reads through io::read_regular_file's type and size checks.
bool regular_file_exists(const std::string& path, void*) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}
std::string path_unchanged(const std::string& path, void*) {
  return path;
}
bool read_checked(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                  void*) {
  try {
    const std::string bytes = io::read_regular_file(path, "glTF resource", kMaxGltfInputBytes);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const std::exception& e) {
    if (err) *err = e.what();
    return false;
  }
}
bool refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err = "skinsim never writes glTF files";
  return false;
}

std::string lower_extension(const std::string& path) {
  return lowercase(fs::path(path).extension().string());
}

// The file's bytes and its JSON, checked as parse_gltf_file needs them before tinygltf runs.
struct GltfFile {
  std::string bytes;
  bool binary = false;
  fs::path dir;
  std::vector<fs::path> external;
};

GltfFile read_gltf_file(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw SceneError(fmt::format("{}: file not found (or not a regular file)", path));
  }
  const std::string ext = lower_extension(path);
  if (ext != ".gltf" && ext != ".glb") {
    throw SceneError(fmt::format("{}: expected a .gltf or .glb file", path));
  }
  GltfFile f;
  try {
    f.bytes = io::read_regular_file(path, "glTF file", kMaxGltfInputBytes);
  } catch (const io::InputError& e) {
    throw SceneError(fmt::format("{}: {}", path, e.what()));
  }
  f.binary = ext == ".glb";
  const std::string_view json =
      f.binary ? glb_json_chunk(f.bytes, path) : std::string_view(f.bytes);
  check_depth(json, path);
  f.dir = fs::path(path).parent_path();
  f.external = external_files(json, f.dir, path);
  return f;
}

}  // namespace

std::string content_fingerprint_of(const std::string& path) {
  const GltfFile f = read_gltf_file(path);
  std::string parts = content_fingerprint(f.bytes);
  for (const fs::path& file : f.external) {
    try {
      parts +=
          content_fingerprint(io::read_regular_file(file, "glTF resource", kMaxGltfInputBytes));
    } catch (const io::InputError& e) {
      throw SceneError(fmt::format("{}: {}", path, e.what()));
    }
  }
  return f.external.empty() ? parts : content_fingerprint(parts);
}

tinygltf::Model parse_gltf_file(const std::string& path) {
  const GltfFile f = read_gltf_file(path);
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&decode_unless_in_buffer_view, nullptr);
  loader.SetFsCallbacks(
      {&regular_file_exists, &path_unchanged, &read_checked, &refuse_write, nullptr});
  tinygltf::Model model;
  std::string err, warn;
  bool ok = false;
  try {
    const auto* data = reinterpret_cast<const unsigned char*>(f.bytes.data());
    const auto size = static_cast<unsigned int>(f.bytes.size());
    const std::string base = f.dir.empty() ? std::string(".") : f.dir.string();
    ok = f.binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, data, size, base)
                  : loader.LoadASCIIFromString(&model, &err, &warn, f.bytes.data(), size, base);
  } catch (const std::exception& e) {  // tinygltf's JSON layer may throw on odd input
    fail(path, e.what());
  }
  if (!ok) {
    if (err.empty()) err = warn;
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    fail(path, err.empty() ? "unknown error" : err);
  }
  return model;
}

}  // namespace skinsim::scene::gltf
