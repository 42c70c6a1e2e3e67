#include "driver/frame/reference_store.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <utility>
#include <vector>

#include "util/fingerprint.h"
#include "util/text.h"
#include "util/user_error.h"

namespace skinsim::driver {

namespace fs = std::filesystem;

namespace {

constexpr const char* kCacheVariable = "SKINSIM_CACHE_DIR";
constexpr const char* kStem = "reference_";
constexpr const char* kMarkerSuffix = ".json";

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

}  // namespace

std::optional<fs::path> cache_directory() {
  const std::string chosen = environment(kCacheVariable);
  const auto refuse = [&chosen](const std::string& why) {
    throw UserError(
        fmt::format("environment variable {} is '{}', {}: name a directory for "
                    "skinsim's cache, or 'off' for none",
                    kCacheVariable, sanitized(chosen, 200), why));
  };
  if (lowercase(chosen) == "off") return std::nullopt;
  if (!chosen.empty()) {
    if (sanitized(chosen, chosen.size()) != chosen) refuse("which holds control characters");
    std::error_code ec;
    const fs::file_status status = fs::status(chosen, ec);
    if (fs::exists(status) && !fs::is_directory(status)) refuse("which is not a directory");
    if (!fs::exists(status) && fs::is_symlink(fs::symlink_status(chosen, ec))) {
      refuse("a symlink to nothing");
    }
    return fs::path(chosen);
  }
  // XDG Base Directory Specification: a relative XDG_CACHE_HOME is to be ignored.
  const fs::path xdg = environment("XDG_CACHE_HOME");
  if (xdg.is_absolute()) return xdg / "skinsim";
  const std::string home = environment("HOME");
  if (!home.empty()) return fs::path(home) / ".cache" / "skinsim";
  return std::nullopt;
}

void evict_least_recent(const fs::path& dir, const std::string& stem,
                        const std::vector<std::string>& suffixes, int capacity) {
  std::vector<std::pair<fs::file_time_type, fs::path>> markers;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.starts_with(stem) && name.ends_with(kMarkerSuffix)) {
      markers.emplace_back(entry.last_write_time(), entry.path());
    }
  }
  if (markers.size() <= static_cast<std::size_t>(capacity)) return;
  std::sort(markers.begin(), markers.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;  // newest first
  });
  for (std::size_t i = static_cast<std::size_t>(capacity); i < markers.size(); ++i) {
    fs::path base = markers[i].second;
    base.replace_extension();
    std::error_code ec;
    fs::remove(markers[i].second, ec);  // the marker first: the images are then no copy
    for (const std::string& suffix : suffixes) fs::remove(base.string() + suffix, ec);
  }
}

ReferenceStore::ReferenceStore(fs::path dir, int capacity)
    : dir_(std::move(dir)), capacity_(std::max(capacity, 1)) {}

std::optional<ReferenceStore> ReferenceStore::from_environment() {
  const std::optional<fs::path> cache = cache_directory();
  if (!cache) return std::nullopt;
  return ReferenceStore(*cache / "references");
}

// One file name per marker: the marker's hash, so that two builds, scenes or reference knob
// settings never share a file. The marker stored beside the images rules out a collision.
fs::path ReferenceStore::file(const nlohmann::json& marker, const std::string& suffix) const {
  return dir_ / (kStem + fnv1a64_hex(marker.dump()) + suffix);
}

KeptReference ReferenceStore::load(const nlohmann::json& marker, int width, int height) const {
  const fs::path marker_file = file(marker, kMarkerSuffix);
  KeptReference kept = load_marked_reference(marker_file, marker, width, height,
                                             file(marker, ".png"), file(marker, "_skin.png"));
  std::error_code ec;
  if (kept.images) fs::last_write_time(marker_file, fs::file_time_type::clock::now(), ec);  // used
  return kept;
}

std::string ReferenceStore::keep(const nlohmann::json& marker,
                                 const ReferenceImages& images) const {
  try {
    fs::create_directories(dir_);
    save_marked_reference(marker, images, file(marker, kMarkerSuffix), file(marker, ".png"),
                          file(marker, "_skin.png"));
    evict();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

void ReferenceStore::evict() const {
  evict_least_recent(dir_, kStem, {".png", "_skin.png"}, capacity_);
}

}  // namespace skinsim::driver
