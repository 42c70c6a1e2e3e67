#include "pipeline/knob_types.h"

#include <fmt/format.h>

#include <cmath>
#include <tuple>

#include "util/parse_number.h"

namespace skinsim::pipeline {

namespace {

// A row's name, option, accepted values and help; the builders add the behaviour.
KnobSpec row(std::string name, std::string flag, std::string values, std::string help) {
  KnobSpec k;
  k.name = std::move(name);
  k.flag = std::move(flag);
  k.values = std::move(values);
  k.help = std::move(help);
  return k;
}

bool power_of_two(int v) {
  return v > 0 && (v & (v - 1)) == 0;
}

std::string power_of_two_range(int lo, int hi) {
  return fmt::format("power of two in [{}, {}]", lo, hi);
}

}  // namespace

bool Interval::contains(float v) const {
  // The bounds as the knob's float holds them: "0.05" typed for (0.05, ...] is 0.05f, which
  // as a double lies above 0.05 and would pass an open bound it equals.
  const auto lo_f = static_cast<float>(lo), hi_f = static_cast<float>(hi);
  const bool above = lo_open ? v > lo_f : v >= lo_f;
  const bool below = hi_open ? v < hi_f : v <= hi_f;
  return above && below;  // NaN fails both
}

std::string Interval::text() const {
  return fmt::format("{}{:g}, {:g}{}", lo_open ? '(' : '[', lo, hi, hi_open ? ')' : ']');
}

float parse_knob_float(const std::string& key, const std::string& text) {
  if (const auto v = parse_real<float>(text)) return *v;
  throw ConfigError(fmt::format("{}: expected a finite decimal number, got '{}'", key, text));
}

int parse_knob_int(const std::string& key, const std::string& text) {
  if (const auto v = parse_integer<int>(text)) return *v;
  throw ConfigError(fmt::format("{}: expected a decimal integer, got '{}'", key, text));
}

glm::vec3 parse_knob_rgb(const std::string& key, const std::string& text) {
  const auto c1 = text.find(',');
  const auto c2 = c1 == std::string::npos ? c1 : text.find(',', c1 + 1);
  if (c2 == std::string::npos || text.find(',', c2 + 1) != std::string::npos) {
    throw ConfigError(fmt::format("{}: expected three numbers 'r,g,b', got '{}'", key, text));
  }
  return {parse_knob_float(key, text.substr(0, c1)),
          parse_knob_float(key, text.substr(c1 + 1, c2 - c1 - 1)),
          parse_knob_float(key, text.substr(c2 + 1))};
}

KnobSpec real_knob(std::string name, std::string flag, std::string help, ConfigField<float> field,
                   Interval range) {
  KnobSpec k = row(std::move(name), std::move(flag), "number in " + range.text(), std::move(help));
  k.set = [field, key = k.name](PipelineConfig& c, const std::string& text) {
    field(c) = parse_knob_float(key, text);
  };
  k.get = [field](const PipelineConfig& c) { return fmt::format("{}", field(c)); };
  k.invalid = [field, range, key = k.name](const PipelineConfig& c) -> std::string {
    if (range.contains(field(c))) return "";
    return fmt::format("{} must be in {}, got {:g}", key, range.text(), field(c));
  };
  return k;
}

KnobSpec optional_real_knob(std::string name, std::string flag, std::string help,
                            ConfigField<std::optional<float>> field, Interval range) {
  KnobSpec k = row(std::move(name), std::move(flag), "number in " + range.text() + " or auto",
                   std::move(help));
  k.set = [field, key = k.name](PipelineConfig& c, const std::string& text) {
    field(c) = text == "auto" ? std::nullopt : std::optional(parse_knob_float(key, text));
  };
  k.get = [field](const PipelineConfig& c) {
    return field(c) ? fmt::format("{}", *field(c)) : std::string("auto");
  };
  k.invalid = [field, range, key = k.name](const PipelineConfig& c) -> std::string {
    if (!field(c) || range.contains(*field(c))) return "";
    return fmt::format("{} must be in {}, got {:g}", key, range.text(), *field(c));
  };
  return k;
}

KnobSpec shapes_reference(KnobSpec knob) {
  knob.reference = true;
  return knob;
}

KnobSpec swept_by(KnobSpec knob, std::string sweep_flag, std::string sweep_help) {
  knob.sweep_flag = std::move(sweep_flag);
  knob.sweep_help = std::move(sweep_help);
  return knob;
}

KnobSpec switch_knob(std::string name, std::string flag, std::string help,
                     ConfigField<bool> field) {
  KnobSpec k = row(std::move(name), std::move(flag), "on or off", std::move(help));
  k.set = [field, key = k.name](PipelineConfig& c, const std::string& text) {
    try {
      field(c) = parse_switch(text);
    } catch (const ConfigError& e) {
      throw ConfigError(key + ": " + e.what());
    }
  };
  k.get = [field](const PipelineConfig& c) { return std::string(switch_name(field(c))); };
  k.invalid = [](const PipelineConfig&) { return std::string(); };
  return k;
}

KnobSpec optional_rgb_knob(std::string name, std::string flag, std::string help,
                           ConfigField<std::optional<glm::vec3>> field, Interval range) {
  KnobSpec k = row(std::move(name), std::move(flag), "r,g,b each in " + range.text() + ", or auto",
                   std::move(help));
  k.set = [field, key = k.name](PipelineConfig& c, const std::string& text) {
    field(c) = text == "auto" ? std::nullopt : std::optional(parse_knob_rgb(key, text));
  };
  k.get = [field](const PipelineConfig& c) {
    if (!field(c)) return std::string("auto");
    const glm::vec3 v = *field(c);
    return fmt::format("{},{},{}", v.r, v.g, v.b);
  };
  k.invalid = [field, range, key = k.name](const PipelineConfig& c) -> std::string {
    if (!field(c)) return "";
    const glm::vec3 v = *field(c);
    if (range.contains(v.r) && range.contains(v.g) && range.contains(v.b)) return "";
    return fmt::format("{} must be in {} per channel, got {:g},{:g},{:g}", key, range.text(), v.r,
                       v.g, v.b);
  };
  return k;
}

KnobSpec integer_knob(std::string name, std::string flag, std::string help, ConfigField<int> field,
                      int lo, int hi, bool power_of_two_only) {
  KnobSpec k;
  k.name = std::move(name);
  k.flag = std::move(flag);
  k.values =
      power_of_two_only ? power_of_two_range(lo, hi) : fmt::format("integer in [{}, {}]", lo, hi);
  k.help = std::move(help);
  k.set = [field, key = k.name](PipelineConfig& c, const std::string& text) {
    field(c) = parse_knob_int(key, text);
  };
  k.get = [field](const PipelineConfig& c) { return std::to_string(field(c)); };
  k.invalid = [=, key = k.name](const PipelineConfig& c) -> std::string {
    const int v = field(c);
    if (v >= lo && v <= hi && (!power_of_two_only || power_of_two(v))) return "";
    return fmt::format(
        "{} must be {}, got {}", key,
        power_of_two_only ? "a " + power_of_two_range(lo, hi) : fmt::format("in [{}, {}]", lo, hi),
        v);
  };
  return k;
}

KnobSpec size_knob(std::string name, std::string flag, std::string help, ConfigField<int> width,
                   ConfigField<int> height, int lo, int hi) {
  KnobSpec k = row(std::move(name), std::move(flag),
                   fmt::format("WxH, powers of two in [{}, {}]", lo, hi), std::move(help));
  k.set = [=, key = k.name](PipelineConfig& c, const std::string& text) {
    std::tie(width(c), height(c)) = parse_size(text, key);
  };
  k.get = [=](const PipelineConfig& c) { return fmt::format("{}x{}", width(c), height(c)); };
  k.invalid = [=, key = k.name](const PipelineConfig& c) -> std::string {
    const auto ok = [&](int v) { return v >= lo && v <= hi && power_of_two(v); };
    if (ok(width(c)) && ok(height(c))) return "";
    return fmt::format("{} must be powers of two in [{}, {}] per axis, got {}x{}", key, lo, hi,
                       width(c), height(c));
  };
  return k;
}

}  // namespace skinsim::pipeline
