// Bounds the nesting depth of JSON text before a recursive parser sees it: tinygltf's JSON
// parser recurses once per '[' or '{', so a 35 KB file of nested arrays overflows the stack.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace skinsim::scene::gltf {

// Real glTF files nest fewer than 20 levels (root, array, object, extras...); 64 leaves room
// for deep `extras` while staying far from any stack limit.
inline constexpr int kMaxJsonDepth = 64;

// Byte offset of the first '[' or '{' (outside strings) that opens level max_depth + 1, or
// nullopt when the text never nests deeper than max_depth. Does not validate the JSON.
std::optional<std::size_t> find_nesting_beyond(std::string_view json, int max_depth);

}  // namespace skinsim::scene::gltf
