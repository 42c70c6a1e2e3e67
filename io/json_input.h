// Reading JSON that a user may have edited or planted (results, shard status, cache markers,
// baselines, glTF) with its nesting bounded before any parser sees it: a parser that recurses
// once per '[' or '{' overflows the stack on a few tens of KB of nested arrays, and even an
// iterative one builds a tree that later recursive code (comparison, dump, destruction) walks.
#pragma once

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>

#include "io/read_file.h"

namespace skinsim::io {

// Real inputs nest fewer than 20 levels (a glTF's root, array, object, extras; a sweep's
// results.json about 6); 64 leaves room for deep glTF `extras` while staying far from any
// stack limit.
inline constexpr int kMaxJsonDepth = 64;

// Byte offset of the first '[' or '{' (outside strings) that opens level max_depth + 1, or
// nullopt when the text never nests deeper than max_depth. Does not validate the JSON.
std::optional<std::size_t> find_nesting_beyond(std::string_view json, int max_depth);

// Throws InputError "<what> <source>: JSON nests deeper than ..." when `text` does, for a
// reader that parses it itself (and reports its own parse errors).
void require_json_depth(std::string_view text, std::string_view what,
                        const std::filesystem::path& source);

// Parses `text`, read from `source` (a path, for messages). Throws InputError
// "<what> <source>: ..." when it nests deeper than kMaxJsonDepth or is not JSON.
nlohmann::json parse_json(std::string_view text, std::string_view what,
                          const std::filesystem::path& source);

// `text` parsed, or a discarded value when it nests too deep or is not JSON: for readers of
// files skinsim wrote that treat a damaged one as missing (stored results, caches).
nlohmann::json parse_json_or_discarded(std::string_view text);

// read_regular_file, then parse_json.
nlohmann::json read_json_file(const std::filesystem::path& path, std::string_view what,
                              std::uintmax_t max_bytes = kMaxTextFileBytes);

}  // namespace skinsim::io
