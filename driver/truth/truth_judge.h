// Judging with a truth (`run --truth`, docs/validation.md): where the truth comes from (the
// truth store, Blender Cycles, or a file the user brings) and every quality metric of an image
// against it, beside the Monte Carlo noise floor the truth carries. A difference below that
// floor is never called visible: a pixel counts as visibly different from the truth only when
// its FLIP error is above quality::flip_visibility_threshold() and above the FLIP error between
// the truth and another seed's rendering there (the largest within 2 pixels: one pixel's is
// one draw of the noise).
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "driver/truth/truth_scene.h"
#include "driver/truth/truth_store.h"
#include "image/image.h"
#include "pipeline/config.h"
#include "pipeline/gpu_scene.h"
#include "util/user_error.h"

namespace skinsim::driver {

// What `--truth` takes: "cached", or a file.
inline constexpr const char* kCachedTruth = "cached";

// Which truth `--truth cached` takes: Cycles' samples and the first seed (the noise floor's
// is the next), set by --truth-samples and --truth-seed (`skinsim truth`'s --samples and
// --seed). A truth so named is only looked up, never rendered on the way: one of many
// samples may take hours, so `skinsim truth` renders it where it should (docs/validation.md).
struct TruthChoice {
  int samples = TruthSettings{}.samples;
  int seed = 1;
  bool named = false;  // --truth-samples or --truth-seed given

  // "--truth-samples 256 --truth-seed 1", for messages.
  std::string options() const;
};

// Throws UserError when `choice` is named but `spec` is not "cached" (a file is one image).
void require_cached_for_choice(const std::string& spec, const TruthChoice& choice);

// The UserError for a named truth the store lacks: names the options, the store and the
// `skinsim truth` command that renders it (`view`: e.g. "--resolution 256x192").
UserError missing_named_truth(const TruthChoice& choice, const std::string& store,
                              const std::string& view);

struct Truth {
  TruthImages images;
  nlohmann::json about;        // where it came from: {"source", "file" or "key"/"store"}
  image::ScalarMap floor_map;  // the floor per pixel (above); empty without a second seed
};

// `truth` with `images`, and the floor map of their second seed when there is one.
Truth with_images(Truth truth, TruthImages images);

// The truth store's (truth_store.h) truth of `scene`'s view under `config` with `choice`'s
// samples and seeds: when the store has none (or has it damaged: `note` says so), rendered
// with Blender Cycles with seeds `seed` and `seed + 1` (the second for the noise floor) and
// kept; rendered every time when the store is off. A named choice is never rendered: missing,
// it throws missing_named_truth. `threads`: Blender's (0: its own choice). Throws UserError
// when Blender is missing (its version is in the key) or fails.
Truth cached_truth(const pipeline::GpuScene& scene, const pipeline::PipelineConfig& config,
                   const TruthChoice& choice, int threads,
                   const std::function<void(const std::string&)>& note);

// Throws UserError naming `option` when `spec` is neither "cached", an existing file nor a
// `skinsim truth` directory: checked before a command's work, as the file is read only after it.
void require_truth(const std::string& option, const std::string& spec);

// A truth the user brings (`--truth FILE`): a PNG is taken as seen (sRGB, 8 bits), anything
// else is read through skinsim-exr as scene-linear (OpenEXR, Radiance HDR, TIFF) and encoded
// for display. One image has no second seed, so no measured floor. A directory `skinsim truth`
// wrote (`--truth DIR`, any samples) is its truth.exr, and with --noise-floor its second seed,
// whose floor is measured. Throws UserError naming `option` and the file when it is missing,
// unreadable or not width x height.
Truth truth_file(const std::string& option, const std::filesystem::path& path, int width,
                 int height);

// PSNR, SSIM, FLIP and the visible pixels (the rule above) of `test` against the truth over
// every pixel ("all") and, with `skin` showing any, over the skin ("skin").
nlohmann::json judge_against_truth(const image::Image& test, const Truth& truth,
                                   const image::Mask* skin);

// The truth's noise floor: the second seed judged as above (its visible pixels are 0 by the
// rule), or {"measured": false, "why": ...} without one.
nlohmann::json truth_noise_floor(const Truth& truth, const image::Mask* skin);

// Where the truth came from, for the terminal: "the truth store's .../truth_<key>.json (64
// samples, seeds 1 and 2, Blender 3.4.1)", "rendered with Blender Cycles (...)", "the file F
// (one image)".
std::string truth_source_text(const Truth& truth);

// "skin PSNR 30.21 dB, SSIM 0.812, FLIP 0.125, visibly different on 12.3% (810 px)": a
// judge_against_truth or truth_noise_floor result, the skin's figures when there are any.
std::string truth_figures(const nlohmann::json& judged);

}  // namespace skinsim::driver
