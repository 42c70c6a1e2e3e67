// Escaping and the base style of the HTML pages.
#include "reports/html_text.h"

#include <fmt/format.h>

#include <algorithm>

namespace skinsim::reports {

const char* const kPageStyle = R"(
body { font-family: system-ui, sans-serif; margin: 2em auto; max-width: 1400px; color: #222; }
h1 { font-size: 1.6em; } h2 { margin-top: 1.6em; border-bottom: 1px solid #ccc; }
table { border-collapse: collapse; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: right; }
th { background: #eee; } th.text, td.text { text-align: left; }
.wide { overflow-x: auto; max-width: 100%; }
)";

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
