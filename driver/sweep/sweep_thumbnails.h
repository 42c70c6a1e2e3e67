// Small copies of a sweep's full-size images (references, frames, error maps) for the report
// page, so it loads tens of kilobytes per image instead of megabytes; the full-size files stay
// where they are and the page links them.
#pragma once

#include <filesystem>

#include "image/image.h"
#include "results/sweep_table.h"

namespace skinsim::driver {

inline constexpr int kThumbnailWidth = 320;  // pixels; the page shows them 160-330 px wide

// Writes reports::thumbnail_path(image) for every image the table names that has none yet, or
// a thumbnail older than the image. Images that do not exist are skipped (the report then has
// no thumbnail for them and links nothing that is missing).
void write_thumbnails(const results::SweepTable& table, const std::filesystem::path& sweep_dir);

// Writes `image` as the PNG `relative` (a path inside sweep_dir), then its thumbnail, made from
// the pixels in memory instead of the file read back: the thumbnail write_thumbnails would make
// from that PNG, byte for byte, without decoding it (a sweep's frames and error maps: 32
// PNGs of 2048x1536 decoded after the last configuration, otherwise). Takes the image to
// round it in place: a frame's copy would be 36 MiB more at the sweep's peak. Returns the PNG's
// xxh3_fingerprint (util/fingerprint.h), of the bytes written.
std::string write_image_and_thumbnail(image::Image image, const std::filesystem::path& sweep_dir,
                                      const std::string& relative);

}  // namespace skinsim::driver
