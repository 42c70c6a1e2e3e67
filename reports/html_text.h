// What every skinsim HTML page shares: escaping of text and attributes (html_escape) and of
// link targets (url_encode_path), and the base style (fonts, headings, tables).
#pragma once

#include <string>

namespace skinsim::reports {

// CSS for body text, headings and right-aligned number tables (.text: left-aligned text;
// .wide: a table that scrolls inside the page).
extern const char* const kPageStyle;

// Escapes &, <, >, " and ' for HTML text and attribute values.
std::string html_escape(const std::string& text);

// Percent-encodes a relative path for use as a URL (keeps A-Z a-z 0-9 - . _ ~ /).
std::string url_encode_path(const std::string& path);

// Where the report looks for the small copy of an image (a path relative to the sweep
// directory, like `image`): thumbs/<image with '/' as '_'>. The sweep writes these
// (driver/sweep_thumbnails.h); the page shows them and links the full-size image.
std::string thumbnail_path(const std::string& image);

}  // namespace skinsim::reports
