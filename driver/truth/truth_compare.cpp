#include "driver/truth/truth_compare.h"

#include <fmt/format.h>

#include "driver/frame/frame_job.h"
#include "driver/frame/reference_cache.h"
#include "driver/truth/truth_judge.h"
#include "io/json_input.h"
#include "io/read_file.h"
#include "util/user_error.h"

namespace skinsim::driver {

namespace fs = std::filesystem;

namespace {

constexpr const char* kOption = "compare --truth";

image::Image run_frame(const fs::path& run) {
  if (!fs::is_regular_file(run / "result.json") || !fs::is_regular_file(run / "frame.png")) {
    throw UserError(
        fmt::format("{}: {} is not a run directory (result.json, frame.png); a "
                    "sweep is judged with `sweep --truth`",
                    kOption, run.string()));
  }
  return image::load_png(run / "frame.png");
}

// The key of the cached truth `run` was judged with.
nlohmann::json judged_key(const fs::path& run) {
  const fs::path file = run / "result.json";
  const nlohmann::json result =
      io::parse_json(io::read_regular_file(file, "result.json"), "result.json", file);
  const nlohmann::json truth = result.value("truth", nlohmann::json::object());
  if (!truth.is_object() || !truth.contains("key")) {
    throw UserError(
        fmt::format("{} cached: {} was not judged by a cached truth (run it with "
                    "--truth cached, or give a truth file)",
                    kOption, run.string()));
  }
  return truth["key"];
}

Truth kept_truth(const fs::path& a, const fs::path& b, int width, int height,
                 const TruthChoice& choice) {
  nlohmann::json key = judged_key(a);
  if (judged_key(b) != key) {
    throw UserError(
        fmt::format("{} cached: {} and {} were judged by different truths (other "
                    "views or settings): compare runs of one view",
                    kOption, a.string(), b.string()));
  }
  const std::optional<TruthStore> store = TruthStore::from_environment();
  if (!store) {
    throw UserError(fmt::format("{} cached: the truth store is off (SKINSIM_CACHE_DIR)", kOption));
  }
  if (choice.named) key = with_samples(key, choice.samples, choice.seed);
  KeptTruth kept = store->load(key, width, height);
  if (!kept.images && choice.named) {
    throw missing_named_truth(choice, "the truth store " + store->dir().string(),
                              fmt::format("--resolution {}x{}", width, height));
  }
  if (!kept.images) {
    throw UserError(fmt::format(
        "{} cached: the truth store no longer holds {} intact{}: run {} again with --truth cached",
        kOption, store->marker(key).string(),
        kept.discarded.empty() ? "" : " (" + kept.discarded + ")", a.string()));
  }
  Truth truth;
  truth.about = {{"source", "store"}, {"key", key}, {"store", store->marker(key).string()}};
  return with_images(std::move(truth), std::move(*kept.images));
}

}  // namespace

nlohmann::json compare_with_truth(const fs::path& a, const fs::path& b, const std::string& spec,
                                  const TruthChoice& choice) {
  const image::Image frame_a = run_frame(a), frame_b = run_frame(b);
  if (frame_a.width != frame_b.width || frame_a.height != frame_b.height) {
    throw UserError(fmt::format("{}: {} is {}x{}, {} {}x{}: one truth cannot judge both", kOption,
                                a.string(), frame_a.width, frame_a.height, b.string(),
                                frame_b.width, frame_b.height));
  }
  const Truth truth = spec == kCachedTruth
                          ? kept_truth(a, b, frame_a.width, frame_a.height, choice)
                          : truth_file("--truth", spec, frame_a.width, frame_a.height);
  std::optional<image::Mask> skin;
  const fs::path mask = a / reference_mask_path(kRunReferenceImage);
  if (fs::is_regular_file(mask)) skin = image::load_mask_png(mask);
  const image::Mask* m = skin && skin->count() > 0 ? &*skin : nullptr;
  nlohmann::json out{{"truth", truth.about},
                     {"noise_floor", truth_noise_floor(truth, m)},
                     {"a", judge_against_truth(frame_a, truth, m)},
                     {"b", judge_against_truth(frame_b, truth, m)}};
  const char* region = m ? "skin" : "all";
  const double fa = out["a"][region]["flip"].get<double>(),
               fb = out["b"][region]["flip"].get<double>();
  out["closer"] = fa < fb ? "a" : fb < fa ? "b" : "same";
  return out;
}

std::vector<std::string> truth_compare_lines(const nlohmann::json& judged) {
  const std::string closer = judged["closer"].get<std::string>();
  return {
      fmt::format("truth: {}; its noise floor: {}",
                  judged["truth"]["source"] == "file" ? judged["truth"]["file"].get<std::string>()
                                                      : judged["truth"]["store"].get<std::string>(),
                  truth_figures(judged["noise_floor"])),
      fmt::format("A vs truth: {}", truth_figures(judged["a"])),
      fmt::format("B vs truth: {}", truth_figures(judged["b"])),
      closer == "same"
          ? std::string("A and B are equally close to the truth (FLIP)")
          : fmt::format("{} is closer to the truth (FLIP)", closer == "a" ? "A" : "B")};
}

}  // namespace skinsim::driver
