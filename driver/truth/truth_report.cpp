#include "driver/truth/truth_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "driver/truth/truth_judge.h"
#include "reports/html_text.h"
#include "reports/recommendation.h"

namespace skinsim::driver {

namespace {

std::string id_text(const nlohmann::json& id) {
  return id.is_null() ? std::string("none (nothing within the budget)") : id.get<std::string>();
}

// "Blender Cycles (Blender 3.4.1), 64 samples, seeds 1 and 2, from the truth store (…)": where
// the truth of a group came from (truth_judge.h Truth::about).
std::string source_text(const nlohmann::json& about) {
  if (about["source"] == "file") {
    return "the file " + about["file"].get<std::string>() +
           " (one image, so its noise floor is not measured)";
  }
  const nlohmann::json& key = about["key"];
  const std::string settings = fmt::format(
      "Blender Cycles ({}), {} samples, seeds {} and {}", key["blender"].get<std::string>(),
      key["samples"].get<int>(), key["seed"].get<int>(), key["second_seed"].get<int>());
  if (about["source"] == "store") {
    return settings + ", from the truth store (" + about["store"].get<std::string>() + ")";
  }
  return settings + ", rendered for this sweep";
}

std::string figure(const results::ConfigResult& row, const std::string& metric) {
  const auto it = row.quality.find(metric);
  return it == row.quality.end() ? std::string("-") : fmt::format("{:.4f}", it->second);
}

// Whether this truth can tell the group's configurations apart: the spread of their FLIP
// against it beside the FLIP its own noise makes.
std::string separation_html(const std::vector<const results::ConfigResult*>& rows,
                            const std::string& truth_metric, const nlohmann::json& group,
                            const char* region) {
  if (rows.size() < 2) return "<p>One configuration: nothing to separate.</p>\n";
  const nlohmann::json& floor = group["noise_floor"];
  if (!floor.value("measured", false)) {
    return "<p>The truth is one image, so its noise floor is not measured: whether the "
           "configurations' differences against it exceed its own noise is unknown (<code>--truth "
           "cached</code> renders two seeds and measures it).</p>\n";
  }
  double lo = INFINITY, hi = -INFINITY;
  for (const results::ConfigResult* r : rows) {
    const double v = r->quality.at(truth_metric);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  const double spread = hi - lo;
  const double floor_flip = floor[region]["flip"].get<double>();
  std::string h = reports::esc(fmt::format(
      "Against the truth the configurations' {} lies between {:.4f} and {:.4f} (a spread of "
      "{:.4f}); the truth's noise floor is FLIP {:.4f} (its two seeds against each other).",
      truth_metric, lo, hi, spread, floor_flip));
  if (spread >= floor_flip) {
    return "<p>" + h + " The spread is above the floor: this truth separates them.</p>\n";
  }
  h += " <b>The spread is below the noise floor: this truth cannot separate the "
       "configurations.</b>";
  if (!group["recommendation_same"].get<bool>()) {
    h += " Its different recommendation above is within its noise.";
  }
  const int samples = group["truth"]["key"]["samples"].get<int>();
  const std::optional<double> needed = samples_to_separate(floor_flip, spread, samples);
  if (!needed) {
    return "<p>" + h + " Their frames are equally far from it; no sample count would.</p>\n";
  }
  h += reports::esc(fmt::format(
      " A truth of about {:.0f} samples would (an estimate: its noise, and the floor's FLIP "
      "with it, taken to fall as 1/sqrt(samples) from the floor measured at {} samples).",
      *needed, samples));
  h += " Render it with <code>" +
       reports::esc(fmt::format("skinsim truth --samples {:.0f} --noise-floor", *needed)) +
       "</code> and the group's scene, device and knob options, and judge with <code>" +
       reports::esc(fmt::format("--truth cached --truth-samples {:.0f}", *needed)) + "</code>.";
  return "<p>" + h + "</p>\n";
}

std::string group_html(const results::SweepTable& table, const nlohmann::json& group,
                       const std::string& metric) {
  const char* region = metric == "flip_skin" ? "skin" : "all";
  const std::string truth_metric = "truth_" + metric;
  const std::string visible = metric == "flip_skin" ? "truth_visible_skin" : "truth_visible_frame";
  const std::string name = group["group"].get<std::string>();
  std::vector<const results::ConfigResult*> rows;
  for (const results::ConfigResult& r : table.rows) {
    if (r.group == name && r.quality.count(truth_metric)) rows.push_back(&r);
  }
  std::string h = "<h3>" + reports::esc(name.empty() ? "All configurations" : name) + "</h3>\n";
  h += "<p><b>Truth:</b> " + reports::esc(source_text(group["truth"])) + ". <b>Noise floor:</b> " +
       reports::esc(truth_figures(group["noise_floor"])) + ".</p>\n";
  const std::string by_reference = id_text(group["recommended_by_reference"]);
  h += group["recommendation_same"].get<bool>()
           ? "<p><b>Recommendation: the same</b> under the truth as under the reference: " +
                 reports::esc(by_reference) + ".</p>\n"
           : "<p><b>Recommendation: changed</b>: " + reports::esc(by_reference) +
                 " under the reference, " + reports::esc(id_text(group["recommended_by_truth"])) +
                 " under the truth (" + reports::esc(group["verdict_by_truth"].get<std::string>()) +
                 ").</p>\n";
  const nlohmann::json& changed = group["visibility_verdicts_changed"];
  const int verdicts = group["visibility_verdicts"].get<int>();
  h += "<p>" + reports::esc(fmt::format("{} of {} \"visibly different\" verdicts stay",
                                        verdicts - static_cast<int>(changed.size()), verdicts));
  if (changed.empty()) {
    h += ".</p>\n";
  } else {
    h += "; flipped:</p>\n<ul>\n";
    const auto says = [](const nlohmann::json& v) {
      return v.get<bool>() ? "visibly different" : "not visibly different";
    };
    for (const nlohmann::json& c : changed) {
      h += "<li><code>" + reports::esc(c["id"].get<std::string>()) +
           "</code>: " + says(c["visible_by_reference"]) + " from the reference, " +
           says(c["visible_by_truth"]) + " from the truth</li>\n";
    }
    h += "</ul>\n";
  }
  h += separation_html(rows, truth_metric, group, region);
  h += "<table>\n<tr><th>configuration</th><th>" + reports::esc(metric) + " vs reference</th><th>" +
       reports::esc(metric) +
       " vs truth</th><th>visible vs reference</th><th>visible vs truth</th></tr>\n";
  for (const results::ConfigResult* r : rows) {
    h += "<tr><td class=\"text\">" + reports::esc(r->label.empty() ? r->id : r->label) +
         "</td><td>" + figure(*r, metric) + "</td><td>" + figure(*r, truth_metric) +
         "</td><td class=\"text\">" + (r->visible_vs_reference ? "yes" : "no") +
         "</td><td class=\"text\">" +
         (r->quality.count(visible) && r->quality.at(visible) > 0.0 ? "yes" : "no") +
         "</td></tr>\n";
  }
  return h + "</table>\n";
}

}  // namespace

std::optional<double> samples_to_separate(double floor_flip, double spread, int samples) {
  if (!(spread > 0.0)) return std::nullopt;
  const double ratio = floor_flip / spread;
  return std::ceil(samples * ratio * ratio);
}

std::string truth_report_section(const results::SweepTable& table, const nlohmann::json& judged) {
  if (!judged.is_array() || judged.empty()) return "";
  const std::string metric = reports::recommend_metric(table.rows);
  std::string h =
      "<h2>Judged by truth</h2>\n<div class=\"summary\">\n<p>Every configuration was judged a "
      "second time, with a path-traced truth of its group's view (Blender Cycles, random-walk "
      "subsurface scattering; docs/validation.md) in the reference's place. The truth image is "
      "Cycles' linear Rec.709 radiance encoded for display as the reference is: the exact sRGB "
      "transfer function, clamped to [0, 1], rounded to 8 bits, with no exposure change or tone "
      "curve (skinsim applies none). The frames aim at the same encoding; their skin's "
      "<code>gamma</code> knob approximates the sRGB curve (gamma 2.0 by default), and what "
      "that changes counts as their error against either judge. The truth is one of the "
      "slider's frames below, and the crops show it and |recommended - truth|.</p>\n<p>A truth "
      "carries Monte Carlo noise. Its <i>noise "
      "floor</i> is the FLIP error between it and a second rendering with the next seed; a "
      "pixel counts as visibly different from the truth only where its FLIP error is above "
      "the visibility threshold <i>and</i> above that floor (the largest within 2 pixels), so "
      "the truth's own noise is never called a visible difference.</p>\n";
  for (const nlohmann::json& group : judged) h += group_html(table, group, metric);
  return h + "</div>\n";
}

std::map<std::string, std::string> truth_report_images(const nlohmann::json& judged) {
  std::map<std::string, std::string> images;
  if (!judged.is_array()) return images;
  for (const nlohmann::json& g : judged) {
    if (g.contains("image")) images[g["group"].get<std::string>()] = g["image"].get<std::string>();
  }
  return images;
}

}  // namespace skinsim::driver
