// What every skinsim HTML page shares: escaping of text and attributes (escape_markup, util/text.h)
// and of link targets (url_encode_path), and the base style (fonts, headings, tables).
#pragma once

#include <string>

#include "util/text.h"  // escape_markup

namespace skinsim::reports {

// CSS for body text, headings and right-aligned number tables (.text: left-aligned text;
// .wide: a table that scrolls inside the page).
extern const char* const kPageStyle;

// Percent-encodes a relative path for use as a URL (keeps A-Z a-z 0-9 - . _ ~ /).
std::string url_encode_path(const std::string& path);

// Text as element content or a quoted attribute value.
inline std::string esc(const std::string& s) {
  return escape_markup(s);
}

// A relative path as an href or src value.
inline std::string link(const std::string& path) {
  return esc(url_encode_path(path));
}

// Where the report looks for the small copy of an image (a path relative to the sweep
// directory, like `image`): thumbs/<image with '/' as '_'>. The sweep writes these
// (driver/sweep/sweep_thumbnails.h); the page shows them and links the full-size image.
std::string thumbnail_path(const std::string& image);

}  // namespace skinsim::reports
