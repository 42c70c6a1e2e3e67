// The knob table: the knobs every technique uses, then each technique's own, and the
// functions every interface reaches them through.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "pipeline/config.h"
#include "pipeline/knob_types.h"
#include "pipeline/light_knobs.h"
#include "pipeline/technique.h"

namespace skinsim::pipeline {

namespace {

KnobSpec technique_knob() {
  KnobSpec k;
  k.decides = true;
  k.name = "technique";
  k.flag = "--technique";
  k.values = fmt::format("{}", fmt::join(technique_names(), ", "));
  k.help = "Skin technique (docs/techniques.md)";
  k.sweep_flag = "--techniques";
  k.sweep_help = "Techniques (" + k.values +
                 ") or 'all'; an axis a technique does not use (e.g. scales for wrap, LUT sizes "
                 "with an analytic specular) runs once for it, at the default";
  k.id_prefix = "";
  k.set = [](PipelineConfig& c, const std::string& text) {
    c.technique = find_technique(text).name;
  };
  k.get = [](const PipelineConfig& c) { return c.technique; };
  k.invalid = [](const PipelineConfig& c) -> std::string {
    try {
      find_technique(c.technique);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "";
  };
  return k;
}

KnobSpec resolution_knob() {
  KnobSpec k;
  k.reference = true;
  k.name = "resolution";
  k.flag = "--resolution";
  k.values = "WxH within 16..8192 per axis and 0.1..10 wide per high, or display";
  k.help = "Render resolution (default: the device's display)";
  k.sweep_flag = "--resolutions";
  k.sweep_help = "Render resolutions WxH, or 'display' for the device's (default)";
  k.id_prefix = "";
  k.set = [](PipelineConfig& c, const std::string& text) {
    std::tie(c.width, c.height) =
        text == "display" ? std::pair{0, 0} : parse_size(text, "resolution");
  };
  k.get = [](const PipelineConfig& c) {
    return c.width == 0 ? std::string("display") : fmt::format("{}x{}", c.width, c.height);
  };
  k.invalid = [](const PipelineConfig& c) -> std::string {
    if ((c.width == 0) != (c.height == 0)) return "resolution needs both width and height";
    if (c.width != 0 && (c.width < 16 || c.width > 8192 || c.height < 16 || c.height > 8192)) {
      return fmt::format("resolution must be within 16..8192 per axis, got {}x{}", c.width,
                         c.height);
    }
    // The cameras frame a head at aspect ratios 0.1 to 10 (scene/procedural_head.cpp).
    const double aspect = c.width == 0 ? 1.0 : static_cast<double>(c.width) / c.height;
    if (aspect < 0.1 || aspect > 10.0) {
      return fmt::format("resolution {}x{} is {:.3g} wide per high; it must be 0.1..10", c.width,
                         c.height, aspect);
    }
    return "";
  };
  return k;
}

KnobSpec lobe_knob(const std::string& name, SpecularLobe PipelineConfig::*field,
                   const std::string& help) {
  KnobSpec k;
  k.reference = true;
  k.name = name;
  k.flag = "--" + name;
  k.values = "roughness,weight: roughness in [0.05, 1], weight in [0, 1]";
  k.help = help;
  k.set = [field, name](PipelineConfig& c, const std::string& text) {
    const auto comma = text.find(',');
    if (comma == std::string::npos) {
      throw ConfigError(fmt::format("{}: expected 'roughness,weight', got '{}'", name, text));
    }
    c.*field = {parse_knob_float(name, text.substr(0, comma)),
                parse_knob_float(name, text.substr(comma + 1))};
  };
  k.get = [field](const PipelineConfig& c) {
    return fmt::format("{},{}", (c.*field).roughness, (c.*field).weight);
  };
  k.invalid = [field, name](const PipelineConfig& c) -> std::string {
    const SpecularLobe& lobe = c.*field;
    if (!(lobe.roughness >= 0.05f && lobe.roughness <= 1.0f)) {
      return fmt::format("{}.roughness must be in [0.05, 1], got {:g}", name, lobe.roughness);
    }
    if (!(lobe.weight >= 0.0f && lobe.weight <= 1.0f)) {
      return fmt::format("{}.weight must be in [0, 1], got {:g}", name, lobe.weight);
    }
    return "";
  };
  return k;
}

KnobSpec lut_format_knob() {
  KnobSpec k;
  k.name = "lut_format";
  k.flag = "--lut-format";
  k.values = "rgba8 or rgba16f";
  k.help = "BRDF LUT texel format (the paper's mobile formats); read only with specular ks_lut";
  k.sweep_flag = "--lut-formats";
  k.sweep_help = "BRDF LUT formats: rgba8,rgba16f";
  k.id_prefix = "";
  k.set = [](PipelineConfig& c, const std::string& text) {
    try {
      c.lut_format = sim::parse_format(text);
    } catch (const std::invalid_argument& e) {
      throw ConfigError(std::string("lut_format: ") + e.what());
    }
  };
  k.get = [](const PipelineConfig& c) { return std::string(sim::format_name(c.lut_format)); };
  k.invalid = [](const PipelineConfig& c) -> std::string {
    if (c.lut_format != sim::TexelFormat::kRGBA32F) return "";
    return "lut_format must be rgba8 or rgba16f (the paper's mobile formats)";
  };
  k.applies = reads_brdf_lut;
  return k;
}

KnobSpec specular_knob() {
  KnobSpec k = choice_knob("specular", "--specular",
                           "Specular model of the skin shaders; only ks_lut reads the BRDF LUT",
                           "ks_lut, ks, ggx or dual_ggx", &PipelineConfig::specular, parse_specular,
                           specular_name);
  k.decides = true;
  k.applies = uses_specular_knob;
  return k;
}

}  // namespace

const std::vector<KnobSpec>& common_knobs() {
  static const std::vector<KnobSpec> knobs = [] {
    KnobSpec lut =
        size_knob("lut", "--lut", "BRDF LUT size (N.H x N.V); read only with specular ks_lut",
                  &PipelineConfig::lut_width, &PipelineConfig::lut_height, 2, 1024);
    lut.applies = reads_brdf_lut;
    lut = swept_by(std::move(lut), "--luts",
                   "BRDF LUT sizes WxH, e.g. 8x32,16x64,32x128,64x256 (default sweep: those)");
    KnobSpec gamma =
        choice_knob("gamma", "--gamma", "Skin gamma: gamma 2.0 as in GPU Pro 5, or exact sRGB",
                    "square or srgb", &PipelineConfig::gamma, parse_gamma, gamma_name);
    gamma.sweep_flag = "--gammas";
    gamma.sweep_help = "Skin gammas: square,srgb (the exact curves cost ALU; docs/techniques.md)";
    gamma.id_prefix = "";
    std::vector<KnobSpec> rows{
        technique_knob(),
        resolution_knob(),
        integer_knob("msaa", "--msaa",
                     "MSAA samples per pixel of the framebuffer render (background, eyes, skin), "
                     "at the standard 2x/4x positions, resolved on chip at the tile store; "
                     "offscreen passes stay 1x",
                     &PipelineConfig::msaa, 1, 4, true),
        std::move(gamma),
        lobe_knob("lobe1", &PipelineConfig::lobe1,
                  "First specular lobe (Beckmann m and weight; the weights sum to 1)"),
        lobe_knob("lobe2", &PipelineConfig::lobe2, "Second specular lobe"),
        shapes_reference(real_knob("specular_intensity", "--specular-intensity",
                                   "Specular intensity rho_s (d'Eon & Luebke)",
                                   &PipelineConfig::specular_intensity, {0.0, 1.0})),
        specular_knob(),
        choice_knob("skin_precision", "--skin-precision",
                    "Default float precision of the skin fragment shader (GLSL ES `precision "
                    "... float;`): highp computes in FP32; mediump rounds every value to FP16 "
                    "and its ALU ops cost the device's alu.mediump_op_cost",
                    "highp or mediump", &PipelineConfig::skin_precision, parse_precision,
                    precision_name),
        std::move(lut),
        lut_format_knob(),
        shapes_reference(choice_knob(
            "reference_profile", "--reference-profile",
            "Diffusion profile of the reference every technique is measured against: d'Eon & "
            "Luebke's six Gaussians or Jensen et al. 2001's dipole (Skin1)",
            "six_gaussian or dipole", &PipelineConfig::reference_profile, parse_reference_profile,
            reference_profile_name)),
    };
    for (KnobSpec& k : light_knobs()) rows.push_back(std::move(k));
    return rows;
  }();
  return knobs;
}

const std::vector<KnobSpec>& all_knobs() {
  static const std::vector<KnobSpec> knobs = [] {
    std::vector<KnobSpec> all = common_knobs();
    // A row several techniques share (the pre-integrated LUT's size) is listed once.
    for (const TechniqueSpec* t : all_techniques()) {
      for (const KnobSpec& k : t->knobs) {
        const auto named = [&](const KnobSpec& known) { return known.name == k.name; };
        if (std::none_of(all.begin(), all.end(), named)) all.push_back(k);
      }
    }
    return all;
  }();
  return knobs;
}

const KnobSpec& find_knob(const std::string& name) {
  for (const KnobSpec& k : all_knobs()) {
    if (k.name == name) return k;
  }
  throw ConfigError(fmt::format("unknown pipeline setting '{}' (known: {})", name,
                                fmt::join(config_field_names(), ", ")));
}

void set_config_field(PipelineConfig& config, const std::string& key, const std::string& value) {
  find_knob(key).set(config, value);
}

std::string get_config_field(const PipelineConfig& config, const std::string& key) {
  return find_knob(key).get(config);
}

const std::vector<std::string>& config_field_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const KnobSpec& k : all_knobs()) v.push_back(k.name);
    return v;
  }();
  return names;
}

void PipelineConfig::validate() const {
  for (const KnobSpec& k : all_knobs()) {
    if (std::string why = k.invalid(*this); !why.empty()) throw ConfigError(why);
  }
  // Between knobs: the two specular lobes split one energy.
  if (!(std::fabs(lobe1.weight + lobe2.weight - 1.0f) < 1e-3f)) {
    throw ConfigError(
        fmt::format("lobe weights must sum to 1, got {:g} + {:g}", lobe1.weight, lobe2.weight));
  }
}

}  // namespace skinsim::pipeline
