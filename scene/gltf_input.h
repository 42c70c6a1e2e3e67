// Reads a .gltf or .glb into a tinygltf::Model without trusting it. Before tinygltf sees the
// file: the file and every external buffer/image it names must be a regular file of at most
// kMaxGltfInputBytes (a FIFO, directory or /dev/zero is refused, not read), a GLB's header and
// chunk lengths must agree with the file, and the JSON may nest at most io::kMaxJsonDepth levels.
// Every failure throws SceneError starting with the glTF file's path.
#pragma once

#include <cstdint>
#include <string>

namespace tinygltf {
class Model;
}

namespace skinsim::scene::gltf {

// Per file read: the .gltf/.glb itself and each external buffer or image. Head scans with
// textures are tens of MiB; this refuses runaway inputs long before memory is at risk.
inline constexpr std::uintmax_t kMaxGltfInputBytes = std::uintmax_t{512} << 20;

tinygltf::Model parse_gltf_file(const std::string& path);

// content_fingerprint (util/fingerprint.h) of the file's bytes, or, where it names external
// buffers or images, of the file's and each of theirs: what a stored result made from the
// scene must match. Checks and errors as parse_gltf_file's.
std::string content_fingerprint_of(const std::string& path);

}  // namespace skinsim::scene::gltf
