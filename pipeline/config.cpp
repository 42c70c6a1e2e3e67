#include "pipeline/config.h"

#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <tuple>

#include "util/parse_number.h"

namespace skinsim::pipeline {

namespace {
void require(bool ok, const std::string& message) {
  if (!ok) throw ConfigError(message);
}
bool power_of_two(int v) { return v > 0 && (v & (v - 1)) == 0; }
}  // namespace

void PipelineConfig::validate() const {
  require(std::isfinite(buffer_scale) && buffer_scale > 0.0f && buffer_scale <= 1.0f,
          fmt::format("scale must be in (0, 1], got {:g}", buffer_scale));
  require(power_of_two(lut_width) && lut_width >= 2 && lut_width <= 1024,
          fmt::format("lut width must be a power of two in [2, 1024], got {}", lut_width));
  require(power_of_two(lut_height) && lut_height >= 2 && lut_height <= 1024,
          fmt::format("lut height must be a power of two in [2, 1024], got {}", lut_height));
  require(lut_format != sim::TexelFormat::kRGBA32F,
          "lut_format must be rgba8 or rgba16f (the paper's mobile formats)");
  require(blur_iterations >= 1 && blur_iterations <= 8,
          fmt::format("blur_iterations must be in [1, 8], got {}", blur_iterations));
  if (blur_width_mm) {
    require(std::isfinite(*blur_width_mm) && *blur_width_mm > 0.0f && *blur_width_mm <= 50.0f,
            fmt::format("blur_width_mm must be in (0, 50], got {:g}", *blur_width_mm));
  }
  require(std::isfinite(normal_offset_mm) && normal_offset_mm >= 0.0f && normal_offset_mm <= 20.0f,
          fmt::format("normal_offset_mm must be in [0, 20], got {:g}", normal_offset_mm));
  for (const auto& [name, lobe] : {std::pair{"lobe1", lobe1}, std::pair{"lobe2", lobe2}}) {
    require(lobe.roughness >= 0.05f && lobe.roughness <= 1.0f,
            fmt::format("{}.roughness must be in [0.05, 1], got {:g}", name, lobe.roughness));
    require(lobe.weight >= 0.0f && lobe.weight <= 1.0f,
            fmt::format("{}.weight must be in [0, 1], got {:g}", name, lobe.weight));
  }
  require(std::fabs(lobe1.weight + lobe2.weight - 1.0f) < 1e-3f,
          fmt::format("lobe weights must sum to 1, got {:g} + {:g}", lobe1.weight, lobe2.weight));
  require(specular_intensity >= 0.0f && specular_intensity <= 1.0f,
          fmt::format("specular_intensity must be in [0, 1], got {:g}", specular_intensity));
  require((width == 0) == (height == 0), "resolution needs both width and height");
  require(width == 0 || (width >= 16 && width <= 8192 && height >= 16 && height <= 8192),
          fmt::format("resolution must be within 16..8192 per axis, got {}x{}", width, height));
  require(std::isfinite(lod_distance_m) && lod_distance_m > 0.0f,
          fmt::format("lod_distance_m must be > 0, got {:g}", lod_distance_m));
  require(power_of_two(preintegrated_lut_width) && preintegrated_lut_width >= 4 &&
              preintegrated_lut_width <= 1024 && power_of_two(preintegrated_lut_height) &&
              preintegrated_lut_height >= 4 && preintegrated_lut_height <= 1024,
          fmt::format("preintegrated_lut must be powers of two in [4, 1024] per axis, got {}x{}",
                      preintegrated_lut_width, preintegrated_lut_height));
  require(std::isfinite(wrap) && wrap >= 0.0f && wrap <= 1.0f,
          fmt::format("wrap must be in [0, 1], got {:g}", wrap));
  require(burley_samples >= 4 && burley_samples <= kMaxBurleySamples,
          fmt::format("burley_samples must be in [4, {}], got {}", kMaxBurleySamples,
                      burley_samples));
  if (burley_distance_mm) {
    const glm::vec3 d = *burley_distance_mm;
    for (int c = 0; c < 3; ++c) {
      require(std::isfinite(d[c]) && d[c] >= 0.01f && d[c] <= 20.0f,
              fmt::format("burley_distance_mm must be in [0.01, 20] mm per channel, got {:g},{:g},{:g}",
                          d.r, d.g, d.b));
    }
  }
  require(power_of_two(texture_space_size) && texture_space_size >= 64 &&
              texture_space_size <= 4096,
          fmt::format("texture_space_size must be a power of two in [64, 4096], got {}",
                      texture_space_size));
}

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

namespace {

float parse_float(const std::string& key, const std::string& text) {
  if (const auto v = parse_real<float>(text)) return *v;
  throw ConfigError(fmt::format("{}: expected a finite decimal number, got '{}'", key, text));
}

int parse_int(const std::string& key, const std::string& text) {
  if (const auto v = parse_integer<int>(text)) return *v;
  throw ConfigError(fmt::format("{}: expected a decimal integer, got '{}'", key, text));
}

glm::vec3 parse_rgb(const std::string& key, const std::string& text) {
  const auto c1 = text.find(',');
  const auto c2 = c1 == std::string::npos ? c1 : text.find(',', c1 + 1);
  if (c2 == std::string::npos) {
    throw ConfigError(fmt::format("{}: expected 'r,g,b', got '{}'", key, text));
  }
  return {parse_float(key, text.substr(0, c1)), parse_float(key, text.substr(c1 + 1, c2 - c1 - 1)),
          parse_float(key, text.substr(c2 + 1))};
}

SpecularLobe parse_lobe(const std::string& key, const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos) {
    throw ConfigError(fmt::format("{}: expected 'roughness,weight', got '{}'", key, text));
  }
  return {parse_float(key, text.substr(0, comma)), parse_float(key, text.substr(comma + 1))};
}

}  // namespace

void set_config_field(PipelineConfig& c, const std::string& key, const std::string& value) {
  if (key == "technique") {
    c.technique = parse_technique(value);
  } else if (key == "scale") {
    c.buffer_scale = parse_float(key, value);
  } else if (key == "lut") {
    std::tie(c.lut_width, c.lut_height) = parse_size(value, key);
  } else if (key == "lut_format") {
    try {
      c.lut_format = sim::parse_format(value);
    } catch (const std::invalid_argument& e) {
      throw ConfigError(std::string("lut_format: ") + e.what());
    }
  } else if (key == "blur_iterations") {
    c.blur_iterations = parse_int(key, value);
  } else if (key == "blur_width_mm") {
    c.blur_width_mm = value == "auto" ? std::nullopt : std::optional(parse_float(key, value));
  } else if (key == "normal_offset_mm") {
    c.normal_offset_mm = parse_float(key, value);
  } else if (key == "gamma") {
    c.gamma = parse_gamma(value);
  } else if (key == "lobe1") {
    c.lobe1 = parse_lobe(key, value);
  } else if (key == "lobe2") {
    c.lobe2 = parse_lobe(key, value);
  } else if (key == "specular_intensity") {
    c.specular_intensity = parse_float(key, value);
  } else if (key == "resolution") {
    std::tie(c.width, c.height) =
        value == "display" ? std::pair{0, 0} : parse_size(value, key);
  } else if (key == "lod_distance_m") {
    c.lod_distance_m = parse_float(key, value);
  } else if (key == "specular") {
    c.specular = parse_specular(value);
  } else if (key == "preintegrated_lut") {
    std::tie(c.preintegrated_lut_width, c.preintegrated_lut_height) = parse_size(value, key);
  } else if (key == "curvature") {
    c.curvature = parse_curvature(value);
  } else if (key == "wrap") {
    c.wrap = parse_float(key, value);
  } else if (key == "burley_samples") {
    c.burley_samples = parse_int(key, value);
  } else if (key == "burley_distance_mm") {
    if (value == "auto") {
      c.burley_distance_mm.reset();
    } else {
      c.burley_distance_mm = parse_rgb(key, value);
    }
  } else if (key == "texture_space_size") {
    c.texture_space_size = parse_int(key, value);
  } else {
    throw ConfigError(fmt::format("unknown pipeline setting '{}' (known: {})", key,
                                  fmt::join(config_field_names(), ", ")));
  }
}

const std::vector<std::string>& config_field_names() {
  static const std::vector<std::string> names = {
      "technique", "scale", "lut", "lut_format", "blur_iterations", "blur_width_mm", "normal_offset_mm",
      "gamma", "lobe1", "lobe2", "specular_intensity", "resolution", "lod_distance_m", "specular",
      "preintegrated_lut", "curvature", "wrap", "burley_samples", "burley_distance_mm",
      "texture_space_size"};
  return names;
}

std::string get_config_field(const PipelineConfig& c, const std::string& key) {
  if (key == "technique") return technique_name(c.technique);
  if (key == "scale") return fmt::format("{}", c.buffer_scale);
  if (key == "lut") return fmt::format("{}x{}", c.lut_width, c.lut_height);
  if (key == "lut_format") return sim::format_name(c.lut_format);
  if (key == "blur_iterations") return std::to_string(c.blur_iterations);
  if (key == "blur_width_mm") return c.blur_width_mm ? fmt::format("{}", *c.blur_width_mm) : "auto";
  if (key == "normal_offset_mm") return fmt::format("{}", c.normal_offset_mm);
  if (key == "gamma") return gamma_name(c.gamma);
  if (key == "lobe1") return fmt::format("{},{}", c.lobe1.roughness, c.lobe1.weight);
  if (key == "lobe2") return fmt::format("{},{}", c.lobe2.roughness, c.lobe2.weight);
  if (key == "specular_intensity") return fmt::format("{}", c.specular_intensity);
  if (key == "resolution") {
    return c.width == 0 ? "display" : fmt::format("{}x{}", c.width, c.height);
  }
  if (key == "lod_distance_m") return fmt::format("{}", c.lod_distance_m);
  if (key == "specular") return specular_name(c.specular);
  if (key == "preintegrated_lut") {
    return fmt::format("{}x{}", c.preintegrated_lut_width, c.preintegrated_lut_height);
  }
  if (key == "curvature") return curvature_name(c.curvature);
  if (key == "wrap") return fmt::format("{}", c.wrap);
  if (key == "burley_samples") return std::to_string(c.burley_samples);
  if (key == "burley_distance_mm") {
    if (!c.burley_distance_mm) return "auto";
    const glm::vec3 d = *c.burley_distance_mm;
    return fmt::format("{},{},{}", d.r, d.g, d.b);
  }
  if (key == "texture_space_size") return std::to_string(c.texture_space_size);
  throw ConfigError(fmt::format("unknown pipeline setting '{}'", key));
}

const char* gamma_name(GammaMode mode) { return mode == GammaMode::kSquare ? "square" : "srgb"; }

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

}  // namespace skinsim::pipeline
