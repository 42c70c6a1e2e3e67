// compare.html and compare.json: `skinsim compare`'s result as a page (what changed, what
// moved, the frames side by side with a slider and crops) and as data.
#pragma once

#include <filesystem>

#include "reports/comparison.h"

namespace skinsim::reports {

// The page: self-contained (inline style and script, no network fetches); images are links
// relative to the directory it is written to.
std::string compare_page_html(const Comparison& c);

// Writes dir/compare.html and dir/compare.json, each atomically.
void write_compare_files(const Comparison& c, const std::filesystem::path& dir);

}  // namespace skinsim::reports
