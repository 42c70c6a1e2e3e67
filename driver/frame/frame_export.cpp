#include "driver/frame/frame_export.h"

#include <fmt/format.h>

#include <optional>

#include "driver/frame/frame_export_data.h"
#include "util/check.h"
#include "util/user_error.h"

namespace skinsim::driver {

namespace {

using sim::sl::GlslDialect;

const char* load_name(sim::LoadOp op) {
  switch (op) {
    case sim::LoadOp::kClear:
      return "clear";
    case sim::LoadOp::kLoad:
      return "load";
    case sim::LoadOp::kDontCare:
      return "dont_care";
  }
  return "";
}

const char* cull_name(sim::CullMode mode) {
  switch (mode) {
    case sim::CullMode::kNone:
      return "none";
    case sim::CullMode::kBack:
      return "back";
    case sim::CullMode::kFront:
      return "front";
  }
  return "";
}

// As glBlendFunc: alpha is (SRC_ALPHA, ONE_MINUS_SRC_ALPHA), additive is (ONE, ONE).
const char* blend_name(sim::BlendMode mode) {
  switch (mode) {
    case sim::BlendMode::kOpaque:
      return "opaque";
    case sim::BlendMode::kAlpha:
      return "alpha";
    case sim::BlendMode::kAdditive:
      return "additive";
  }
  return "";
}

const char* filter_name(sim::Filter filter) {
  switch (filter) {
    case sim::Filter::kNearest:
      return "nearest";
    case sim::Filter::kBilinear:
      return "bilinear";
    case sim::Filter::kTrilinear:
      return "trilinear";
  }
  return "";
}

nlohmann::json sampler_json(const sim::SamplerState& s) {
  return {{"filter", filter_name(s.filter)},
          {"wrap", s.wrap == sim::Wrap::kClamp ? "clamp_to_edge" : "repeat"}};
}

// Records each pass once the GPU has run it. Pointers in a pass are valid only then, so
// everything is written down at once.
class FrameRecorder {
 public:
  FrameRecorder(GlslDialect dialect, bool with_data)
      : dialect_(dialect),
        data_(with_data ? std::make_optional<ExportData>(&files_) : std::nullopt) {}

  void record(const sim::RenderPassDesc& pass) {
    const sim::RenderTarget& size = sim::pass_target(pass);
    nlohmann::json p = {{"name", pass.name}, {"size", {size.width, size.height}}};
    if (pass.color) {
      p["color"] = {{"target", pass.color->name},
                    {"format", sim::format_name(pass.color->format)},
                    {"load", load_name(pass.color_load)},
                    {"store", pass.store_color}};
      if (pass.color_load == sim::LoadOp::kClear) {
        const glm::vec4& c = pass.clear_color;
        p["color"]["clear"] = {c.r, c.g, c.b, c.a};
      }
    } else {
      p["color"] = nullptr;
    }
    p["depth"] = {{"load", load_name(pass.depth_load)}, {"store", pass.store_depth}};
    if (pass.depth) {
      p["depth"]["target"] = pass.depth->name;
      p["depth"]["format"] = sim::format_name(pass.depth->format);
    }
    if (pass.render_area) {
      const sim::PixelRect& r = *pass.render_area;
      p["render_area"] = {r.x0, r.y0, r.x1, r.y1};
    }
    if (pass.samples > 1) p["samples"] = pass.samples;  // MSAA, resolved into the target
    nlohmann::json draws = nlohmann::json::array();
    for (const sim::DrawCall& d : pass.draws) draws.push_back(draw(d, size));
    p["draws"] = std::move(draws);
    const std::size_t index = passes_.size();
    for (const auto& [target, part] : {std::pair{pass.color, "color"}, {pass.depth, "depth"}}) {
      if (!target) continue;
      Rendered& rendered = rendered_[target->pixels.data()];
      rendered.pass = pass.name;
      rendered.target = target->name;
      if (data_) {
        rendered.data = data_->target(*target, fmt::format("pass{}_{}_{}", index, pass.name, part));
        p[part]["data"] = rendered.data;
      }
    }
    passes_.push_back(std::move(p));
  }

  ExportedFrame finish(nlohmann::json frame) {
    frame["passes"] = std::move(passes_);
    return {std::move(frame), std::move(files_)};
  }

 private:
  nlohmann::json draw(const sim::DrawCall& d, const sim::RenderTarget& size) {
    const sim::GlslShader vs = d.vertex_program->glsl(dialect_);
    nlohmann::json j = {{"vertex_shader", file_for(d.vertex_program->name(), ".vert", vs.source)}};
    nlohmann::json attributes = nlohmann::json::array();
    for (int a = 0; a < static_cast<int>(sim::VertexAttribute::kCount); ++a) {
      if (vs.interface.attributes.test(static_cast<size_t>(a))) {
        attributes.push_back(sim::attribute_name(static_cast<sim::VertexAttribute>(a)));
      }
    }
    j["geometry"] = {{"vertices", d.geometry.vertex_count},
                     {"triangles", d.geometry.index_count / 3},
                     {"attributes", std::move(attributes)}};
    if (data_) j["geometry"]["data"] = data_->geometry(d.geometry);
    nlohmann::json uniforms = nlohmann::json::object();
    nlohmann::json textures = nlohmann::json::array();
    if (d.fragment_program) {
      const sim::GlslShader fs = d.fragment_program->glsl(dialect_);
      j["fragment_shader"] = file_for(d.fragment_program->name(), ".frag", fs.source);
      // A slot the fragment program reads and the vertex program never writes would be
      // undefined on a GPU (and 0 in the emulator): a bug in the pass, not in the export.
      SKINSIM_CHECK_OP((fs.interface.varyings & ~vs.interface.varyings).to_ulong(), ==, 0ul);
      if (fs.interface.inverse_target_size) {
        uniforms["u_inv_target_size"] = {1.0f / static_cast<float>(size.width),
                                         1.0f / static_cast<float>(size.height)};
      }
      for (int b = 0; b < sim::kMaxTextureBindings; ++b) {
        const sim::SamplerKind kind = fs.interface.samplers[static_cast<size_t>(b)];
        if (kind != sim::SamplerKind::kUnused) textures.push_back(binding(d.textures, b, kind));
      }
    } else {
      j["fragment_shader"] = nullptr;  // depth only
    }
    j["uniforms"] = std::move(uniforms);
    j["textures"] = std::move(textures);
    j["cull"] = cull_name(d.cull);
    j["blend"] = blend_name(d.blend);
    j["depth_test"] = d.depth_test;
    j["depth_write"] = d.depth_write;
    return j;
  }

  nlohmann::json binding(const sim::TextureBindings& bound, int b, sim::SamplerKind kind) {
    nlohmann::json j = {{"binding", b}, {"sampler", fmt::format("s{}", b)}};
    if (kind == sim::SamplerKind::kCube) {
      const sim::TextureCube* cube = bound.cubes[static_cast<size_t>(b)];
      SKINSIM_CHECK(cube != nullptr);
      j.update({{"type", "cube"},
                {"texture", cube->name()},
                {"size", {cube->size(), cube->size()}},
                {"format", sim::format_name(cube->format())},
                {"levels", cube->face(0).level_count()},
                {"sampler_state", sampler_json(cube->sampler())},
                {"rendered_by", nullptr}});  // cube maps are baked, never rendered
      if (data_) j["data"] = data_->cube(*cube);
      return j;
    }
    const sim::Texture2D* t = bound.textures[static_cast<size_t>(b)];
    SKINSIM_CHECK(t != nullptr);
    j.update({{"type", kind == sim::SamplerKind::kShadow ? "2d_shadow" : "2d"},
              {"texture", t->name()},
              {"size", {t->width(), t->height()}},
              {"format", sim::format_name(t->format())},
              {"levels", t->level_count()},
              {"sampler_state", sampler_json(t->sampler())}});
    // A view of a target an earlier pass rendered: the same pixels and name (a freed target's
    // address may be reused by a texture, or by a target filled on the host, such as a LUT).
    const auto it = rendered_.find(t->level(0).texels);
    if (it == rendered_.end() || it->second.target != t->name()) {
      j["rendered_by"] = nullptr;
      if (data_) j["data"] = data_->texture(*t);
    } else {
      j["rendered_by"] = it->second.pass;
      if (data_) j["data"] = it->second.data;  // as that pass left it
    }
    return j;
  }

  // The file a program's source goes to: shaders/NAME.vert, or NAME_2.vert ... where a
  // program of the same name was exported with other uniforms (they are inlined).
  std::string file_for(const std::string& name, const char* extension, const std::string& source) {
    for (int n = 1;; ++n) {
      const std::string path = n == 1 ? fmt::format("shaders/{}{}", name, extension)
                                      : fmt::format("shaders/{}_{}{}", name, n, extension);
      const auto [it, added] = files_.emplace(path, source);
      if (added || it->second == source) return path;
    }
  }

  GlslDialect dialect_;
  nlohmann::json passes_ = nlohmann::json::array();
  std::map<std::string, std::string> files_;
  std::optional<ExportData> data_;  // with --data
  // The last pass that rendered each target (by its pixels), and its data then.
  struct Rendered {
    std::string pass;
    std::string target;
    nlohmann::json data;
  };
  std::map<const glm::vec4*, Rendered> rendered_;
};

}  // namespace

GlslDialect parse_glsl_dialect(const std::string& name) {
  if (name == "es100") return GlslDialect::kEs100;
  if (name == "es300") return GlslDialect::kEs300;
  throw UserError("--glsl must be es100 (OpenGL ES 2.0) or es300 (OpenGL ES 3.0), got '" + name +
                  "'");
}

const char* glsl_dialect_name(GlslDialect dialect) {
  return dialect == GlslDialect::kEs300 ? "es300" : "es100";
}

ExportedFrame export_frame(FrameJob job, GlslDialect dialect, bool with_data) {
  FrameRecorder recorder(dialect, with_data);
  job.capture = [&recorder](const sim::RenderPassDesc& pass) { recorder.record(pass); };
  job.reference = false;
  run_frame_job(job);
  const pipeline::PipelineConfig& config = job.config;
  const gpu_model::DeviceProfile& device = *job.device;
  nlohmann::json knobs = nlohmann::json::object();
  for (const std::string& key : pipeline::config_field_names()) {
    knobs[key] = pipeline::get_config_field(config, key);
  }
  nlohmann::json frame = {
      {"technique", config.technique},
      {"device", device.name},
      {"size", {config.width, config.height}},
      {"glsl", glsl_dialect_name(dialect)},
      {"knobs", knobs},
      {"conventions",
       {{"uniforms", "inlined in the shader source as constants, except those listed per draw"},
        {"varyings", "float slots packed four to a vec4: v_slot0 holds slots 0-3"},
        {"samplers", "uniform sN reads texture binding N"},
        {"blend", "alpha = (SRC_ALPHA, ONE_MINUS_SRC_ALPHA), additive = (ONE, ONE)"},
        {"geometry", "the scene mesh or a screen quad; its vertex data in data/ with --data"},
        {"rows",
         "row 0 of a target is the image's top; gl_FragCoord.y counts from the bottom, so "
         "per-pixel noise seeded by it is mirrored (its statistics are not)"}}}};
  return recorder.finish(std::move(frame));
}

}  // namespace skinsim::driver
