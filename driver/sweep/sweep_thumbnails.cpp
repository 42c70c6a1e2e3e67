#include "driver/sweep/sweep_thumbnails.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "image/resize.h"
#include "reports/html_text.h"
#include "util/fingerprint.h"

namespace skinsim::driver {

namespace fs = std::filesystem;

namespace {

bool up_to_date(const fs::path& thumb, const fs::path& image) {
  std::error_code ec;
  const auto thumb_time = fs::last_write_time(thumb, ec);
  if (ec) return false;
  return thumb_time >= fs::last_write_time(image, ec) && !ec;
}

// `saved`: the pixels load_png reads from `image`'s PNG.
void write_thumbnail(const image::Image& saved, const fs::path& sweep_dir,
                     const std::string& image) {
  image::save_png(image::resized(saved, std::min(kThumbnailWidth, saved.width)),
                  sweep_dir / reports::thumbnail_path(image));
}

}  // namespace

void write_thumbnails(const results::SweepTable& table, const fs::path& sweep_dir) {
  std::set<std::string> images;
  for (const results::ConfigResult& r : table.rows) {
    for (const std::string* image : {&r.reference_image, &r.frame_image, &r.error_image}) {
      if (!image->empty()) images.insert(*image);
    }
  }
  std::vector<std::string> todo;
  for (const std::string& image : images) {
    const fs::path full = sweep_dir / image;
    if (fs::exists(full) && !up_to_date(sweep_dir / reports::thumbnail_path(image), full)) {
      todo.push_back(image);
    }
  }
  if (todo.empty()) return;
  fs::create_directories(sweep_dir / "thumbs");
  tbb::parallel_for(std::size_t{0}, todo.size(), [&](std::size_t i) {
    write_thumbnail(image::load_png(sweep_dir / todo[i]), sweep_dir, todo[i]);
  });
}

std::string write_image_and_thumbnail(image::Image image, const fs::path& sweep_dir,
                                      const std::string& relative) {
  const std::string digest =
      xxh3_fingerprint({image::save_png_and_round(image, sweep_dir / relative).bytes()});
  // After the image: write_thumbnails takes a thumbnail older than its image for a stale one.
  fs::create_directories(sweep_dir / "thumbs");
  write_thumbnail(image, sweep_dir, relative);
  return digest;
}

}  // namespace skinsim::driver
