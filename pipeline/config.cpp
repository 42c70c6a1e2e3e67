#include "pipeline/config.h"

#include <fmt/format.h>

#include "util/parse_number.h"

namespace skinsim::pipeline {

std::pair<int, int> parse_size(const std::string& text, const std::string& what) {
  const auto x = text.find_first_of("xX");
  if (x != std::string::npos) {
    const auto w = parse_integer<int>(std::string_view(text).substr(0, x));
    const auto h = parse_integer<int>(std::string_view(text).substr(x + 1));
    if (w && h && *w > 0 && *h > 0) return {*w, *h};
  }
  throw ConfigError(
      fmt::format("{}: expected WIDTHxHEIGHT with positive integers, got '{}'", what, text));
}

GammaMode parse_gamma(const std::string& text) {
  if (text == "square" || text == "2.0") return GammaMode::kSquare;
  if (text == "srgb") return GammaMode::kSrgb;
  throw ConfigError("gamma: expected 'square' (gamma 2.0) or 'srgb', got '" + text + "'");
}

const char* gamma_name(GammaMode mode) {
  return mode == GammaMode::kSquare ? "square" : "srgb";
}

sim::Precision parse_precision(const std::string& text) {
  if (text == "highp") return sim::Precision::kHighp;
  if (text == "mediump") return sim::Precision::kMediump;
  throw ConfigError("skin_precision: expected 'highp' or 'mediump', got '" + text + "'");
}

const char* precision_name(sim::Precision precision) {
  return precision == sim::Precision::kMediump ? "mediump" : "highp";
}

namespace {
constexpr std::pair<SpecularModel, const char*> kSpecularNames[] = {
    {SpecularModel::kKsLut, "ks_lut"},
    {SpecularModel::kKs, "ks"},
    {SpecularModel::kGgx, "ggx"},
    {SpecularModel::kDualGgx, "dual_ggx"}};
}  // namespace

SpecularModel parse_specular(const std::string& text) {
  for (const auto& [model, name] : kSpecularNames) {
    if (text == name) return model;
  }
  throw ConfigError("specular: expected ks_lut, ks, ggx or dual_ggx, got '" + text + "'");
}

const char* specular_name(SpecularModel model) {
  for (const auto& [m, name] : kSpecularNames) {
    if (m == model) return name;
  }
  return "?";
}

CurvatureSource parse_curvature(const std::string& text) {
  if (text == "vertex") return CurvatureSource::kVertex;
  if (text == "derivatives") return CurvatureSource::kDerivatives;
  throw ConfigError("curvature: expected 'vertex' or 'derivatives', got '" + text + "'");
}

const char* curvature_name(CurvatureSource source) {
  return source == CurvatureSource::kVertex ? "vertex" : "derivatives";
}

ShadowFilter parse_shadow_filter(const std::string& text) {
  if (text == "nearest") return ShadowFilter::kNearest;
  if (text == "pcf2x2") return ShadowFilter::kPcf2x2;
  throw ConfigError("shadow_filter: expected 'nearest' or 'pcf2x2', got '" + text + "'");
}

const char* shadow_filter_name(ShadowFilter filter) {
  return filter == ShadowFilter::kNearest ? "nearest" : "pcf2x2";
}

sim::TexelFormat parse_shadow_depth(const std::string& text) {
  if (text == "depth16") return sim::TexelFormat::kDepth16;
  if (text == "depth24") return sim::TexelFormat::kDepth24;
  throw ConfigError("shadow_depth: expected 'depth16' or 'depth24', got '" + text + "'");
}

const char* shadow_depth_name(sim::TexelFormat format) {
  return sim::format_name(format);
}

ReferenceProfile parse_reference_profile(const std::string& text) {
  if (text == "six_gaussian") return ReferenceProfile::kSixGaussian;
  if (text == "dipole") return ReferenceProfile::kDipole;
  throw ConfigError("reference_profile: expected 'six_gaussian' or 'dipole', got '" + text + "'");
}

const char* reference_profile_name(ReferenceProfile profile) {
  return profile == ReferenceProfile::kSixGaussian ? "six_gaussian" : "dipole";
}

bool parse_switch(const std::string& text) {
  if (text == "on") return true;
  if (text == "off") return false;
  throw ConfigError("expected 'on' or 'off', got '" + text + "'");
}

const char* switch_name(bool on) {
  return on ? "on" : "off";
}

}  // namespace skinsim::pipeline
