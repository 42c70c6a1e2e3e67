#include "scene/json_depth.h"

namespace skinsim::scene::gltf {

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

}  // namespace skinsim::scene::gltf
