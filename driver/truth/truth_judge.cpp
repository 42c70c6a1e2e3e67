#include "driver/truth/truth_judge.h"

#include <fmt/format.h>
#include <stdlib.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>

#include "driver/truth/truth_image.h"
#include "driver/truth/truth_render.h"
#include "driver/truth/truth_scene.h"
#include "io/json_input.h"
#include "quality/json_value.h"
#include "quality/metrics.h"
#include "util/user_error.h"

namespace skinsim::driver {

namespace fs = std::filesystem;

namespace {

// A scratch directory for the exported scene and Blender's output, removed unless an error is
// on its way out (which may name Blender's log in it).
class ScratchDirectory {
 public:
  ScratchDirectory() {
    std::string pattern = (fs::temp_directory_path() / "skinsim-truth-XXXXXX").string();
    if (!mkdtemp(pattern.data())) {
      throw UserError(fmt::format("cannot make a scratch directory in {}: {}",
                                  fs::temp_directory_path().string(), std::strerror(errno)));
    }
    path_ = pattern;
  }
  ~ScratchDirectory() {
    std::error_code ec;
    if (std::uncaught_exceptions() == 0) fs::remove_all(path_, ec);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

bool is_png(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[8] = {};
  in.read(magic, sizeof magic);
  return in && std::memcmp(magic, "\x89PNG\r\n\x1a\n", sizeof magic) == 0;
}

nlohmann::json measure(const image::Image& test, const image::Image& truth,
                       const image::ScalarMap& floor_map, const image::Mask* mask) {
  const quality::FlipResult flip = quality::flip(test, truth, mask);
  std::size_t pixels = 0, visible = 0;
  const double threshold = quality::flip_visibility_threshold();
  for (std::size_t i = 0; i < flip.map.values.size(); ++i) {
    if (mask && mask->values[i] == 0) continue;
    ++pixels;
    const float error = flip.map.values[i];
    if (error > threshold && (floor_map.values.empty() || error > floor_map.values[i])) ++visible;
  }
  return {{"psnr_db", quality::metric_to_json(quality::psnr(test, truth, mask))},
          {"ssim", quality::metric_to_json(quality::ssim(test, truth, mask))},
          {"flip", quality::metric_to_json(flip.mean)},
          {"visible_px", visible},
          {"visible_pct", quality::visible_percent(visible, pixels)},
          {"visible", static_cast<double>(visible) >= quality::flip_visible_area_pixels()}};
}

// The floor at each pixel: the largest two-seed FLIP error within kFloorRadius of it. One
// pixel's two-seed error is a single draw of the noise there, often far below what the noise
// can reach; the largest of the 5x5 neighbours' draws bounds about 24 in 25 of them (the noise
// varies slowly across the face, far more slowly than from draw to draw).
constexpr int kFloorRadius = 2;

image::ScalarMap local_maximum(const image::ScalarMap& map) {
  image::ScalarMap out = map;
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      float peak = 0.0f;
      for (int dy = -kFloorRadius; dy <= kFloorRadius; ++dy) {
        for (int dx = -kFloorRadius; dx <= kFloorRadius; ++dx) {
          const int sx = x + dx, sy = y + dy;
          if (sx < 0 || sy < 0 || sx >= map.width || sy >= map.height) continue;
          peak = std::max(peak, map.values[static_cast<std::size_t>(sy) * map.width + sx]);
        }
      }
      out.values[static_cast<std::size_t>(y) * map.width + x] = peak;
    }
  }
  return out;
}

}  // namespace

Truth with_images(Truth truth, TruthImages images) {
  truth.images = std::move(images);
  if (truth.images.second) {
    truth.floor_map = local_maximum(quality::flip(*truth.images.second, truth.images.image).map);
  }
  return truth;
}

void require_truth(const std::string& option, const std::string& spec) {
  if (spec != kCachedTruth && !fs::is_regular_file(spec) &&
      !fs::is_regular_file(fs::path(spec) / "truth.json")) {
    throw UserError(
        fmt::format("{} {}: no such image file or `skinsim truth` directory (give `{}`, an "
                    "EXR/PNG of the frame's view or a directory `skinsim truth` wrote)",
                    option, spec, kCachedTruth));
  }
}

namespace {

// A directory `skinsim truth` wrote: truth.exr, and with --noise-floor the next seed's image,
// which truth.json names; the two make the floor as a cached truth's do.
Truth truth_directory(const std::string& option, const fs::path& dir, int width, int height) {
  const nlohmann::json made = io::read_json_file(dir / "truth.json", option);
  const auto number = [&](const nlohmann::json& object, const char* field) {
    if (!object.is_object() || !object.contains(field) || !object[field].is_number_integer()) {
      throw UserError(fmt::format("{} {}: no integer '{}' (not a truth.json `skinsim truth` wrote)",
                                  option, (dir / "truth.json").string(), field));
    }
    return object[field].get<int>();
  };
  Truth truth = truth_file(option, dir / "truth.exr", width, height);
  truth.about = {{"source", "directory"},
                 {"dir", dir.string()},
                 {"samples", number(made, "samples")},
                 {"seed", number(made, "seed")}};
  if (!made.contains("noise_floor")) return truth;
  const int second_seed = number(made["noise_floor"], "seed");
  truth.about["second_seed"] = second_seed;
  Truth second =
      truth_file(option, dir / fmt::format("truth_seed{}.exr", second_seed), width, height);
  TruthImages images{std::move(truth.images.image), std::move(second.images.image)};
  return with_images(std::move(truth), std::move(images));
}

}  // namespace

Truth truth_file(const std::string& option, const fs::path& path, int width, int height) {
  require_truth(option, path.string());
  if (fs::is_directory(path)) return truth_directory(option, path, width, height);
  Truth truth;
  if (is_png(path)) {
    truth.images.image = image::load_png(path);
    image::round_to_saved_png(truth.images.image);  // a 16-bit PNG is seen in 8 bits too
  } else {
    const ScratchDirectory scratch;
    try {
      truth.images.image = display_image(read_linear_image(path, scratch.path() / "exr.log"));
    } catch (const UserError& e) {
      throw UserError(fmt::format("{} {}", option, e.what()));
    }
  }
  const image::Image& image = truth.images.image;
  if (image.width != width || image.height != height) {
    throw UserError(
        fmt::format("{} {}: the image is {}x{}, the frame {}x{} (render the truth at the run's "
                    "--resolution, or run at the truth's)",
                    option, path.string(), image.width, image.height, width, height));
  }
  truth.about = {{"source", "file"}, {"file", path.string()}};
  return truth;
}

std::string TruthChoice::options() const {
  return fmt::format("--truth-samples {} --truth-seed {}", samples, seed);
}

void require_cached_for_choice(const std::string& spec, const TruthChoice& choice) {
  if (choice.named && spec != kCachedTruth) {
    throw UserError(fmt::format("{}: only with --truth {} (a truth file is the image it is)",
                                choice.options(), kCachedTruth));
  }
}

UserError missing_named_truth(const TruthChoice& choice, const std::string& store,
                              const std::string& view) {
  return UserError(fmt::format(
      "{}: no truth of this view rendered with {} samples and seeds {} and {} is in {}; render "
      "it with `skinsim truth {} --samples {} --seed {} --noise-floor` and the same scene, "
      "device and knob options (it is kept there), or drop in one rendered elsewhere "
      "(docs/validation.md)",
      choice.options(), choice.samples, choice.seed, choice.seed + 1, store, view, choice.samples,
      choice.seed));
}

Truth cached_truth(const pipeline::GpuScene& scene, const pipeline::PipelineConfig& config,
                   const TruthChoice& choice, int threads,
                   const std::function<void(const std::string&)>& note) {
  TruthSettings settings;
  settings.samples = choice.samples;
  const ScratchDirectory scratch;
  const fs::path dir = scratch.path() / "scene";
  const nlohmann::json exported = write_truth_scene(scene, config, settings, dir);
  const TruthRender render{blender_program(), truth_script(), threads};
  const nlohmann::json key =
      truth_key(exported, dir, render.script, choice.seed, blender_version(render.blender));
  Truth truth;
  truth.about = {{"source", "store"}, {"key", key}};
  const std::optional<TruthStore> store = TruthStore::from_environment();
  const std::string view = fmt::format("--resolution {}x{}", config.width, config.height);
  if (!store && choice.named) {
    throw missing_named_truth(choice, "no store (SKINSIM_CACHE_DIR is off)", view);
  }
  if (store) {
    truth.about["store"] = store->marker(key).string();
    KeptTruth kept = store->load(key, config.width, config.height);
    if (!kept.discarded.empty()) {
      note(fmt::format("the kept truth {} was discarded{}: {}", store->marker(key).string(),
                       choice.named ? "" : ", and is rendered again", kept.discarded));
    }
    if (kept.images) return with_images(std::move(truth), std::move(*kept.images));
    if (choice.named) {
      throw missing_named_truth(choice, "the truth store " + store->dir().string(), view);
    }
  }
  note(fmt::format("rendering the truth with Blender Cycles: {}x{}, {} samples, seeds {} and {}",
                   config.width, config.height, settings.samples, choice.seed, choice.seed + 1));
  const fs::path log = scratch.path() / "blender.log";
  TruthImages rendered;
  for (const int seed : {choice.seed, choice.seed + 1}) {
    const fs::path exr = scratch.path() / fmt::format("truth_seed{}.exr", seed);
    render_truth(render, dir, seed, exr, log);
    image::Image image = display_image(read_linear_image(exr, log));
    (seed == choice.seed ? rendered.image : rendered.second.emplace()) = std::move(image);
  }
  truth.about["source"] = "rendered";
  if (store) {
    const std::string why = store->keep(key, rendered);
    if (!why.empty())
      note(fmt::format("the truth was not kept in {}: {}", store->dir().string(), why));
  }
  return with_images(std::move(truth), std::move(rendered));
}

nlohmann::json judge_against_truth(const image::Image& test, const Truth& truth,
                                   const image::Mask* skin) {
  nlohmann::json out{{"all", measure(test, truth.images.image, truth.floor_map, nullptr)}};
  if (skin && skin->count() > 0)
    out["skin"] = measure(test, truth.images.image, truth.floor_map, skin);
  return out;
}

nlohmann::json truth_noise_floor(const Truth& truth, const image::Mask* skin) {
  if (!truth.images.second) {
    return {{"measured", false},
            {"why",
             "a truth file is one image: `--truth cached` renders two seeds and measures "
             "it"}};
  }
  nlohmann::json floor = judge_against_truth(*truth.images.second, truth, skin);
  floor["measured"] = true;
  return floor;
}

std::string truth_source_text(const Truth& truth) {
  const nlohmann::json& a = truth.about;
  if (a["source"] == "file")
    return fmt::format("the file {} (one image)", a["file"].get<std::string>());
  if (a["source"] == "directory") {
    return fmt::format(
        "the `skinsim truth` directory {} ({} samples, {})", a["dir"].get<std::string>(),
        a["samples"].get<int>(),
        a.contains("second_seed")
            ? fmt::format("seeds {} and {}", a["seed"].get<int>(), a["second_seed"].get<int>())
            : fmt::format("seed {}, no second seed", a["seed"].get<int>()));
  }
  const nlohmann::json& key = a["key"];
  const std::string settings = fmt::format(
      "{} samples, seeds {} and {}, {}", key["samples"].get<int>(), key["seed"].get<int>(),
      key["second_seed"].get<int>(), key["blender"].get<std::string>());
  const std::string kept =
      a.contains("store") ? ", kept as " + a["store"].get<std::string>() : " (the store is off)";
  return a["source"] == "store"
             ? fmt::format("the truth store's {} ({})", a["store"].get<std::string>(), settings)
             : fmt::format("rendered with Blender Cycles ({}){}", settings, kept);
}

std::string truth_figures(const nlohmann::json& judged) {
  if (judged.contains("measured") && !judged["measured"].get<bool>()) return "not measured";
  const bool skin = judged.contains("skin");
  const bool floor = judged.contains("measured");  // the floor is below itself by definition
  const nlohmann::json& m = skin ? judged["skin"] : judged["all"];
  const auto value = [](const nlohmann::json& v, const char* format) {
    return v.is_number() ? fmt::format(fmt::runtime(format), v.get<double>()) : v.dump();
  };
  const std::string figures = fmt::format("{}PSNR {} dB, SSIM {}, FLIP {}", skin ? "skin " : "",
                                          value(m["psnr_db"], "{:.2f}"), value(m["ssim"], "{:.3f}"),
                                          value(m["flip"], "{:.3f}"));
  if (floor) return figures;
  return fmt::format(
      "{}: {} ({:.1f}%, {} px above both the visibility threshold and the noise floor)", figures,
      m["visible"].get<bool>() ? "visibly different" : "not visibly different",
      m["visible_pct"].get<double>(), m["visible_px"].get<std::size_t>());
}

}  // namespace skinsim::driver
