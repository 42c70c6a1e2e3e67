// Text from files a user may have edited (shard status hosts and reasons, environment values)
// made safe to print: a terminal must not receive escape sequences from it, nor megabytes.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>

namespace skinsim {

// `text` with every control character (C0, DEL, and C1 as UTF-8 encodes it, e.g. U+009B
// CSI) replaced by '?', so no escape sequence reaches a terminal, and cut to at most
// `max_bytes` (at a UTF-8 character boundary) with "... (N bytes)" saying how long it was.
inline std::string sanitized(std::string_view text, std::size_t max_bytes) {
  std::size_t kept = std::min(text.size(), max_bytes);
  // Cut before a character, not inside one: back off over UTF-8 continuation bytes.
  while (kept > 0 && kept < text.size() &&
         (static_cast<unsigned char>(text[kept]) & 0xC0) == 0x80) {
    --kept;
  }
  std::string out;
  out.reserve(kept);
  for (std::size_t i = 0; i < kept; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == 0xC2 && i + 1 < kept && static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
        static_cast<unsigned char>(text[i + 1]) <= 0x9F) {
      out += '?';
      ++i;
    } else {
      out += c < 0x20 || c == 0x7F ? '?' : static_cast<char>(c);
    }
  }
  if (kept == text.size()) return out;
  return out + "... (" + std::to_string(text.size()) + " bytes)";
}

// ASCII lower case (for keywords such as "off"; no locale).
inline std::string lowercase(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// `text` safe inside HTML, SVG and XML, as element content and as a quoted attribute value:
// & < > " ' as entities, a newline as &#10; (kept through attribute-value normalisation),
// and the control characters XML 1.0 cannot hold (below 0x20 but tab and carriage return)
// as '?'. One escaper for the report pages and the JUnit file.
inline std::string escape_markup(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
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
      case '\n':
        out += "&#10;";
        break;
      default:
        const auto u = static_cast<unsigned char>(c);
        out += (u < 0x20 && c != '\t' && c != '\r') ? '?' : c;
    }
  }
  return out;
}

}  // namespace skinsim
