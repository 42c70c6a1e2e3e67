#include "reports/comparison.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace skinsim::reports {

double ValueDelta::relative_change() const {
  if (!a || !b) return std::numeric_limits<double>::infinity();
  if (*a == *b) return 0.0;
  if (*a == 0.0) return std::copysign(std::numeric_limits<double>::infinity(), *b);
  return (*b - *a) / std::fabs(*a);
}

bool ValueDelta::moved() const {
  if (!a || !b) return true;
  return std::fabs(*b - *a) > tolerance * std::fabs(*a);
}

bool Comparison::different() const {
  return !added.empty() || !removed.empty() ||
         std::any_of(configs.begin(), configs.end(),
                     [](const ConfigDiff& c) { return c.different(); });
}

std::string visibility_rule_text(const std::string& over) {
  return fmt::format(
      "Visibly different: FLIP between the two frames over {} exceeds the error of one "
      "just-noticeable lightness step (Delta E*ab 2.3) on at least one FLIP digit's area "
      "(0.082 degrees squared, about 30 pixels at 67 pixels per degree).",
      over);
}

namespace {

nlohmann::json optional_number(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

}  // namespace

void to_json(nlohmann::json& j, const ValueDelta& v) {
  const double change = v.relative_change();
  j = {
      {"name", v.name},
      {"kind", v.kind},
      {"a", optional_number(v.a)},
      {"b", optional_number(v.b)},
      {"relative_change", std::isfinite(change) ? nlohmann::json(change) : nlohmann::json(nullptr)},
      {"tolerance", v.tolerance}};
}

void to_json(nlohmann::json& j, const ImageDiff& v) {
  j = {{"a", v.a_image},
       {"b", v.b_image},
       {"identical", v.identical},
       {"visibly_different", v.different()},
       {"flip_over", v.over},
       {"flip_threshold", v.threshold},
       {"visible_area_px", v.visible_area_px},
       {"flip", v.flip},
       {"windows", v.windows}};
  if (!v.size_mismatch.empty()) j["size_mismatch"] = v.size_mismatch;
  if (!v.difference_image.empty()) j["difference_image"] = v.difference_image;
}

void to_json(nlohmann::json& j, const ImageChange& v) {
  j = {{"name", v.name},
       {"a", v.a_image},
       {"b", v.b_image},
       {"differing_px", v.differing_px},
       {"max_difference", v.max_difference}};
  if (!v.size_mismatch.empty()) j["size_mismatch"] = v.size_mismatch;
}

void to_json(nlohmann::json& j, const ConfigDiff& v) {
  j = {{"id", v.id},
       {"different", v.different()},
       {"frame_ms", {{"a", optional_number(v.frame_ms_a)}, {"b", optional_number(v.frame_ms_b)}}},
       {"values_compared", v.values_compared},
       {"moved", v.moved},
       {"other_images", v.other_images}};
  if (v.image) j["image"] = *v.image;
}

void to_json(nlohmann::json& j, const Comparison& v) {
  nlohmann::json changes = nlohmann::json::array();
  for (const SettingChange& c : v.changes)
    changes.push_back({{"name", c.name}, {"a", c.a}, {"b", c.b}});
  j = {{"tool", "skinsim compare"},
       {"kind", v.kind},
       {"a", v.a},
       {"b", v.b},
       {"different", v.different()},
       {"tolerances",
        {{"counter", v.tolerances.counter},
         {"modelled", v.tolerances.modelled},
         {"quality", v.tolerances.quality}}},
       {"changes", changes},
       {"added", v.added},
       {"removed", v.removed},
       {"configs", v.configs},
       {"difference_gain", v.difference_gain},
       {"colour_bar", v.colour_bar}};
}

}  // namespace skinsim::reports
