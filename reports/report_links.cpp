// Checking that every local file report.html links to exists (used by tests and the CLI).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "io/read_file.h"
#include "reports/error.h"
#include "reports/html_report.h"

namespace skinsim::reports {

namespace {

// Inverse of escape_markup (only the entities it produces, plus &#NN; decimal references).
std::string html_unescape(const std::string& text) {
  static const std::regex entity("&(amp|lt|gt|quot|#[0-9]+);");
  std::string out;
  auto begin = std::sregex_iterator(text.begin(), text.end(), entity);
  std::size_t last = 0;
  for (auto it = begin; it != std::sregex_iterator(); ++it) {
    out += text.substr(last, it->position() - last);
    const std::string name = (*it)[1];
    if (name == "amp")
      out += '&';
    else if (name == "lt")
      out += '<';
    else if (name == "gt")
      out += '>';
    else if (name == "quot")
      out += '"';
    else
      out += static_cast<char>(std::stoi(name.substr(1)));
    last = it->position() + it->length();
  }
  return out + text.substr(last);
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string url_decode(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() && hex_value(text[i + 1]) >= 0 &&
        hex_value(text[i + 2]) >= 0) {
      out += static_cast<char>(hex_value(text[i + 1]) * 16 + hex_value(text[i + 2]));
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out;
}

bool is_external(const std::string& link) {
  static const std::regex scheme("^[A-Za-z][A-Za-z0-9+.-]*:");
  return link.empty() || link[0] == '#' || std::regex_search(link, scheme);
}

}  // namespace

std::vector<std::string> missing_report_links(const std::string& dir) {
  const std::filesystem::path page = std::filesystem::path(dir) / "report.html";
  const std::string html = io::read_regular_file(page, "report page");

  static const std::regex attribute(R"re((?:src|href)\s*=\s*"([^"]*)")re", std::regex::icase);
  std::vector<std::string> missing;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), attribute);
       it != std::sregex_iterator(); ++it) {
    std::string link = html_unescape((*it)[1]);
    if (is_external(link)) continue;
    link = url_decode(link.substr(0, link.find_first_of("?#")));
    const bool listed = std::find(missing.begin(), missing.end(), link) != missing.end();
    if (!listed && !std::filesystem::exists(std::filesystem::path(dir) / link)) {
      missing.push_back(link);
    }
  }
  return missing;
}

}  // namespace skinsim::reports
