#include "driver/truth/truth_store.h"

#include <fmt/format.h>

#include <algorithm>
#include <exception>
#include <string_view>
#include <utility>
#include <vector>

#include "driver/frame/reference_cache.h"
#include "driver/frame/reference_store.h"
#include "image/png_encode.h"
#include "io/atomic_file.h"
#include "io/json_input.h"
#include "io/read_file.h"
#include "util/fingerprint.h"

namespace skinsim::driver {

namespace fs = std::filesystem;

namespace {

constexpr const char* kStem = "truth_";
// What this key's rules are: raised when they change, so older entries are no match.
constexpr const char* kKeyFormat = "skinsim truth key 2";
// A scan's meshes.bin and textures may be large; the key reads each whole.
constexpr std::uintmax_t kMaxSceneFileBytes = std::uintmax_t{4} << 30;

std::string_view bytes_of(const image::Image& image) {
  return {reinterpret_cast<const char*>(image.rgb.data()), image.rgb.size() * sizeof(image.rgb[0])};
}

nlohmann::json images_entry(const TruthImages& images) {
  return {{"width", images.image.width},
          {"height", images.image.height},
          {"pixels", xxh3_fingerprint({bytes_of(images.image), bytes_of(*images.second)})}};
}

KeptTruth discarded(std::string why) {
  return {std::nullopt, std::move(why)};
}

}  // namespace

nlohmann::json truth_key(const nlohmann::json& exported, const fs::path& scene_dir,
                         const fs::path& script, int seed, const std::string& blender) {
  // The scene's "source" names the input file where this machine has it: the bytes exported
  // from it are what the truth depends on, wherever they came from. The samples are the
  // key's own field.
  nlohmann::json scene = exported;
  scene.erase("source");
  if (scene.contains("render")) scene["render"].erase("samples");
  const std::string described = scene.dump();
  const std::string meshes = io::read_regular_file(
      scene_dir / exported.value("meshes_file", "meshes.bin"), "truth scene", kMaxSceneFileBytes);
  std::vector<std::string> textures;  // "name", bytes, in name order
  if (fs::is_directory(scene_dir / "textures")) {
    std::vector<fs::path> names;
    for (const fs::directory_entry& e : fs::directory_iterator(scene_dir / "textures")) {
      names.push_back(e.path());
    }
    std::sort(names.begin(), names.end());
    for (const fs::path& name : names) {
      textures.push_back(name.filename().string());
      textures.push_back(io::read_regular_file(name, "truth texture", kMaxSceneFileBytes));
    }
  }
  std::string texture_digests;
  for (const std::string& t : textures) texture_digests += xxh3_fingerprint({t});
  return {{"format", kKeyFormat},
          {"width", exported["width"]},
          {"height", exported["height"]},
          {"samples", exported["render"]["samples"]},
          {"seed", seed},
          {"second_seed", seed + 1},
          {"scene", xxh3_fingerprint({described, meshes, texture_digests})},
          {"script", xxh3_fingerprint({io::read_regular_file(script, "Cycles script")})},
          {"blender", blender}};
}

nlohmann::json with_samples(nlohmann::json key, int samples, int seed) {
  key["samples"] = samples;
  key["seed"] = seed;
  key["second_seed"] = seed + 1;
  return key;
}

TruthStore::TruthStore(fs::path dir, int capacity)
    : dir_(std::move(dir)), capacity_(std::max(capacity, 1)) {}

std::optional<TruthStore> TruthStore::from_environment() {
  const std::optional<fs::path> cache = cache_directory();
  if (!cache) return std::nullopt;
  return TruthStore(*cache / "truths");
}

fs::path TruthStore::file(const nlohmann::json& key, const std::string& suffix) const {
  return dir_ / (kStem + fnv1a64_hex(key.dump()) + suffix);
}

fs::path TruthStore::marker(const nlohmann::json& key) const {
  return file(key, ".json");
}

KeptTruth TruthStore::load(const nlohmann::json& key, int width, int height) const {
  const fs::path marker_file = marker(key);
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(marker_file, ec))) return {};
  nlohmann::json stored;
  try {
    stored =
        io::parse_json(io::read_own_file(marker_file, "truth marker"), "truth marker", marker_file);
  } catch (const std::exception& e) {
    return discarded(e.what());
  }
  if (!stored.is_object()) return discarded("its marker is not a JSON object");
  nlohmann::json described = stored;
  described.erase("images");
  if (described != key) return discarded("its marker holds another key");
  const nlohmann::json entry = stored.value("images", nlohmann::json());
  const auto is = [&entry](const char* name, int value) {
    return entry.is_object() && entry.contains(name) && entry[name] == value;
  };
  if (!is("width", width) || !is("height", height)) {
    return discarded(fmt::format("its marker does not describe {}x{} images", width, height));
  }
  const fs::path image = file(key, ".png"), second = file(key, "_second.png");
  if (!is_plain_file(image) || !is_plain_file(second)) {
    return discarded("its images are missing, or not regular files");
  }
  TruthImages images;
  try {
    images.image = image::load_png(image);
    images.second = image::load_png(second);
  } catch (const std::exception& e) {
    return discarded(e.what());
  }
  if (images.second->width != images.image.width || images.second->height != images.image.height ||
      images_entry(images) != entry) {
    return discarded("its images are not the ones its marker describes");
  }
  fs::last_write_time(marker_file, fs::file_time_type::clock::now(), ec);  // just used
  return {std::move(images), ""};
}

std::string TruthStore::keep(const nlohmann::json& key, const TruthImages& images) const {
  try {
    fs::create_directories(dir_);
    io::replace_file_entry(file(key, ".png"), image::encode_png(images.image, "truth").bytes());
    io::replace_file_entry(file(key, "_second.png"),
                           image::encode_png(*images.second, "truth").bytes());
    nlohmann::json kept = key;
    kept["images"] = images_entry(images);
    io::replace_file_entry(marker(key), kept.dump(2) + "\n");
    evict_least_recent(dir_, kStem, {".png", "_second.png"}, capacity_);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace skinsim::driver
