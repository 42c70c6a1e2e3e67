#include "io/json_input.h"

#include <fmt/format.h>

namespace skinsim::io {

std::optional<std::size_t> find_nesting_beyond(std::string_view json, int max_depth) {
  int depth = 0;
  bool in_string = false;
  bool escaped = false;  // the previous character inside a string was an unescaped '\'
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    switch (c) {
      case '"':
        in_string = true;
        break;
      case '[':
      case '{':
        if (++depth > max_depth) return i;
        break;
      case ']':
      case '}':
        if (depth > 0) --depth;  // unbalanced text is the parser's to report
        break;
      default:
        break;
    }
  }
  return std::nullopt;
}

void require_json_depth(std::string_view text, std::string_view what,
                        const std::filesystem::path& source) {
  if (const std::optional<std::size_t> at = find_nesting_beyond(text, kMaxJsonDepth)) {
    throw InputError(fmt::format("{} {}: JSON nests deeper than {} levels (at byte {})", what,
                                 source.string(), kMaxJsonDepth, *at));
  }
}

nlohmann::json parse_json(std::string_view text, std::string_view what,
                          const std::filesystem::path& source) {
  require_json_depth(text, what, source);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(fmt::format("{} {}: not valid JSON: {}", what, source.string(), e.what()));
  }
}

nlohmann::json parse_json_or_discarded(std::string_view text) {
  if (find_nesting_beyond(text, kMaxJsonDepth)) return nlohmann::json::value_t::discarded;
  return nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
}

nlohmann::json read_json_file(const std::filesystem::path& path, std::string_view what,
                              std::uintmax_t max_bytes) {
  return parse_json(read_regular_file(path, what, max_bytes), what, path);
}

}  // namespace skinsim::io
