#include "reports/html_text.h"

#include <fmt/format.h>

#include <algorithm>

namespace skinsim::reports {

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

std::string url_encode_path(const std::string& path) {
  std::string out;
  for (unsigned char ch : path) {
    const bool keep = (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') ||
                      (ch >= '0' && ch <= '9') || ch == '-' || ch == '.' || ch == '_' ||
                      ch == '~' || ch == '/';
    out += keep ? std::string(1, static_cast<char>(ch)) : fmt::format("%{:02X}", ch);
  }
  return out;
}

std::string thumbnail_path(const std::string& image) {
  std::string name = image;
  std::replace(name.begin(), name.end(), '/', '_');
  return "thumbs/" + name;
}

}  // namespace skinsim::reports
