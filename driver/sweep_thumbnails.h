// Small copies of a sweep's full-size images (references, frames, error maps) for the report
// page, so it loads tens of kilobytes per image instead of megabytes; the full-size files stay
// where they are and the page links them.
#pragma once

#include <filesystem>

#include "reports/sweep_table.h"

namespace skinsim::driver {

inline constexpr int kThumbnailWidth = 320;  // pixels; the page shows them 160-330 px wide

// Writes reports::thumbnail_path(image) for every image the table names that has none yet, or
// a thumbnail older than the image. Images that do not exist are skipped (the report then has
// no thumbnail for them and links nothing that is missing).
void write_thumbnails(const reports::SweepTable& table, const std::filesystem::path& sweep_dir);

}  // namespace skinsim::driver
