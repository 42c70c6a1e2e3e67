// gles_replay: replays a `skinsim export --glsl es300 --data` frame on an OpenGL ES 3.0
// implementation (Mesa llvmpipe through EGL, surfaceless) pass by pass and compares every
// target with the emulator's (docs/validation.md, "Cross-check on llvmpipe").
//
// Each pass is replayed in isolation: its inputs (sampled textures, a target's earlier
// contents) are the emulator's own, from the export, so a difference belongs to that pass.
// Rows: the export keeps the emulator's order (row 0 = the image's top = texture v 0); the
// replay negates gl_Position.y and swaps the front face, so OpenGL's window row 0 (the first
// row in memory) is the emulator's row 0 and every target, texture and gl_FragCoord lines up.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "crosscheck/target_compare.h"

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& message) {
  throw std::runtime_error(message);
}

void check_gl(const std::string& where) {
  const GLenum e = glGetError();
  if (e != GL_NO_ERROR) fail(fmt::format("GL error 0x{:x} at {}", e, where));
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot read " + path.string());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// ------------------------------------------------------------------ EGL
class SurfacelessContext {
 public:
  SurfacelessContext() {
    const auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_display) fail("EGL has no eglGetPlatformDisplayEXT");
    display_ = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
      fail("no surfaceless EGL display (Mesa's libegl-mesa0 and libgl1-mesa-dri)");
    }
    if (!eglBindAPI(EGL_OPENGL_ES_API)) fail("eglBindAPI(OpenGL ES)");
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0,
                                 EGL_NONE};
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT) fail("eglCreateContext (OpenGL ES 3.0)");
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      fail("eglMakeCurrent");
    }
  }
  ~SurfacelessContext() {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
  SurfacelessContext(const SurfacelessContext&) = delete;
  SurfacelessContext& operator=(const SurfacelessContext&) = delete;

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

// ------------------------------------------------------------------ programs
GLuint compile(GLenum stage, const std::string& source, const std::string& name) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    fail(fmt::format("{} does not compile on this GL: {}", name, log));
  }
  return shader;
}

// The vertex shader with its clip-space y negated (see the top of this file).
std::string flipped(std::string source, const std::string& name) {
  const std::string marker = "  gl_Position = ";
  const std::size_t at = source.rfind(marker);
  const std::size_t end = at == std::string::npos ? at : source.find(";\n", at);
  if (end == std::string::npos) fail(name + ": no gl_Position assignment");
  const std::size_t expr = at + marker.size();
  source.replace(expr, end - expr,
                 "vec4(1.0, -1.0, 1.0, 1.0) * (" + source.substr(expr, end - expr) + ")");
  return source;
}

// Writes the fragment depth to colour: what a depth-only pass is compared by (GLES cannot
// read a depth buffer back).
constexpr const char* kDepthToColourFS =
    "#version 300 es\nprecision highp float;\nout vec4 depth;\n"
    "void main() { depth = vec4(gl_FragCoord.z); }\n";

class Programs {
 public:
  explicit Programs(fs::path dir) : dir_(std::move(dir)) {}
  GLuint get(const std::string& vs, const json& fs_file) {
    const std::string fs = fs_file.is_null() ? "" : fs_file.get<std::string>();
    const auto known = programs_.find(vs + "|" + fs);
    if (known != programs_.end()) return known->second;
    const GLuint program = glCreateProgram();
    glAttachShader(program, compile(GL_VERTEX_SHADER, flipped(read_file(dir_ / vs), vs), vs));
    glAttachShader(program,
                   compile(GL_FRAGMENT_SHADER,
                           fs.empty() ? std::string(kDepthToColourFS) : read_file(dir_ / fs),
                           fs.empty() ? "depth-to-colour" : fs));
    glLinkProgram(program);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
      char log[4096];
      glGetProgramInfoLog(program, sizeof log, nullptr, log);
      fail(fmt::format("{} + {} do not link: {}", vs, fs, log));
    }
    return programs_[vs + "|" + fs] = program;
  }

 private:
  fs::path dir_;
  std::map<std::string, GLuint> programs_;
};

// ------------------------------------------------------------------ data
class Files {
 public:
  explicit Files(fs::path dir) : dir_(std::move(dir)) {}
  const std::string& get(const std::string& file) {
    auto it = files_.find(file);
    if (it == files_.end()) it = files_.emplace(file, read_file(dir_ / file)).first;
    return it->second;
  }

 private:
  fs::path dir_;
  std::map<std::string, std::string> files_;
};

struct GlFormat {
  GLenum internal, format, type;
};

GlFormat colour_format(const std::string& name) {
  if (name == "rgba8") return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
  if (name == "rgba16f") return {GL_RGBA16F, GL_RGBA, GL_FLOAT};
  if (name == "rgba32f") return {GL_RGBA32F, GL_RGBA, GL_FLOAT};
  fail("unknown colour format " + name);
}

// A level's texels as GL takes them for `format` (the export's encoding: rgba8 bytes, r32f or
// rgba32f floats). Depth goes to a fixed-point depth texture, exactly as the emulator stores it.
std::vector<std::uint8_t> level_texels(const std::string& blob, std::size_t offset, int w, int h,
                                       const std::string& encoding, const std::string& format,
                                       GlFormat& gl) {
  const std::size_t n = static_cast<std::size_t>(w) * h;
  if (encoding == "r32f") {
    std::vector<float> depth(n);
    std::memcpy(depth.data(), blob.data() + offset, n * sizeof(float));
    std::vector<std::uint8_t> out;
    if (format == "depth16") {
      gl = {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT};
      std::vector<std::uint16_t> v(n);
      for (std::size_t i = 0; i < n; ++i)
        v[i] = static_cast<std::uint16_t>(std::lround(depth[i] * 65535.0));
      out.resize(n * 2);
      std::memcpy(out.data(), v.data(), out.size());
    } else {
      gl = {GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT};
      std::vector<std::uint32_t> v(n);
      for (std::size_t i = 0; i < n; ++i) {
        v[i] = static_cast<std::uint32_t>(std::llround(depth[i] * 16777215.0)) << 8;
      }
      out.resize(n * 4);
      std::memcpy(out.data(), v.data(), out.size());
    }
    return out;
  }
  gl = colour_format(format);
  const std::size_t bytes = n * (encoding == "rgba8" ? 4 : 16);
  return {blob.begin() + static_cast<std::ptrdiff_t>(offset),
          blob.begin() + static_cast<std::ptrdiff_t>(offset + bytes)};
}

void set_sampler_state(GLenum target, const json& binding) {
  const std::string filter = binding["sampler_state"]["filter"];
  const bool mips = binding["levels"].get<int>() > 1;
  GLenum min = GL_NEAREST, mag = GL_NEAREST;
  // As ExecTexUnit filters: bilinear and nearest take the nearest level, trilinear blends two.
  if (filter == "nearest") {
    min = mips ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST;
  } else if (filter == "bilinear") {
    min = mips ? GL_LINEAR_MIPMAP_NEAREST : GL_LINEAR;
    mag = GL_LINEAR;
  } else {
    min = mips ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR;
    mag = GL_LINEAR;
  }
  const GLenum wrap = binding["sampler_state"]["wrap"] == "repeat" ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min));
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(mag));
  glTexParameteri(target, GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
  glTexParameteri(target, GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
  glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, binding["levels"].get<int>() - 1);
  if (binding["type"] == "2d_shadow") {  // EXT_shadow_samplers' compare, LEQUAL
    glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  }
}

// A texture binding's texels, uploaded once per (data file, format, sampler state).
GLuint upload_binding(Files& files, const json& binding) {
  const json& data = binding["data"];
  const std::string format = binding["format"];
  const std::string& blob = files.get(data["file"]);
  GLuint texture = 0;
  glGenTextures(1, &texture);
  GlFormat gl{};
  if (binding["type"] == "cube") {
    glBindTexture(GL_TEXTURE_CUBE_MAP, texture);
    for (int face = 0; face < 6; ++face) {
      const json& levels = data["faces"][face];
      for (int l = 0; l < static_cast<int>(levels.size()); ++l) {
        const int w = levels[l]["size"][0], h = levels[l]["size"][1];
        const auto texels =
            level_texels(blob, levels[l]["offset"], w, h, data["encoding"], format, gl);
        glTexImage2D(static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), l,
                     static_cast<GLint>(gl.internal), w, h, 0, gl.format, gl.type, texels.data());
      }
    }
    set_sampler_state(GL_TEXTURE_CUBE_MAP, binding);
  } else {
    glBindTexture(GL_TEXTURE_2D, texture);
    if (data.contains("levels")) {
      const json& levels = data["levels"];
      for (int l = 0; l < static_cast<int>(levels.size()); ++l) {
        const int w = levels[l]["size"][0], h = levels[l]["size"][1];
        const auto texels =
            level_texels(blob, levels[l]["offset"], w, h, data["encoding"], format, gl);
        glTexImage2D(GL_TEXTURE_2D, l, static_cast<GLint>(gl.internal), w, h, 0, gl.format, gl.type,
                     texels.data());
      }
    } else {  // an earlier pass's target, as the emulator left it
      const int w = data["size"][0], h = data["size"][1];
      const auto texels = level_texels(blob, 0, w, h, data["encoding"], format, gl);
      glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(gl.internal), w, h, 0, gl.format, gl.type,
                   texels.data());
    }
    set_sampler_state(GL_TEXTURE_2D, binding);
  }
  check_gl("uploading " + binding["texture"].get<std::string>());
  return texture;
}

struct Mesh {
  GLuint buffer = 0, indices = 0;
  GLsizei index_count = 0;
};

Mesh upload_mesh(Files& files, const json& data) {
  const std::string& blob = files.get(data["file"]);
  Mesh m;
  glGenBuffers(1, &m.buffer);
  glBindBuffer(GL_ARRAY_BUFFER, m.buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(blob.size()), blob.data(), GL_STATIC_DRAW);
  const std::size_t offset = data["indices"]["offset"];
  m.index_count = data["indices"]["count"];
  glGenBuffers(1, &m.indices);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m.indices);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(static_cast<std::size_t>(m.index_count) * 4),
               blob.data() + offset, GL_STATIC_DRAW);
  return m;
}

// ------------------------------------------------------------------ passes
struct Target {
  GLuint texture = 0, depth = 0, framebuffer = 0;
  GlFormat format{};
  int width = 0, height = 0;
};

// The pass's colour target (a float one receiving the depth of a depth-only pass) and a
// depth buffer, with the target's contents before the pass where the emulator had any.
Target make_target(Files& files, const json& pass, const json* before) {
  Target t;
  t.width = pass["size"][0];
  t.height = pass["size"][1];
  const bool depth_only = pass["color"].is_null();
  t.format = depth_only ? colour_format("rgba32f") : colour_format(pass["color"]["format"]);
  std::vector<std::uint8_t> initial;
  if (before) {
    GlFormat ignored{};
    initial = level_texels(files.get((*before)["file"]), 0, t.width, t.height,
                           (*before)["encoding"], pass["color"]["format"], ignored);
  }
  glGenTextures(1, &t.texture);
  glBindTexture(GL_TEXTURE_2D, t.texture);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(t.format.internal), t.width, t.height, 0,
               t.format.format, t.format.type, initial.empty() ? nullptr : initial.data());
  glGenRenderbuffers(1, &t.depth);
  glBindRenderbuffer(GL_RENDERBUFFER, t.depth);
  const bool depth16 = depth_only && pass["depth"]["format"] == "depth16";
  glRenderbufferStorage(GL_RENDERBUFFER, depth16 ? GL_DEPTH_COMPONENT16 : GL_DEPTH_COMPONENT24,
                        t.width, t.height);
  glGenFramebuffers(1, &t.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.texture, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    fail(
        fmt::format("pass {}: its target is not renderable here", pass["name"].get<std::string>()));
  }
  return t;
}

void set_state(const json& draw) {
  const std::string cull = draw["cull"];
  if (cull == "none") {
    glDisable(GL_CULL_FACE);
  } else {
    glEnable(GL_CULL_FACE);
    glCullFace(cull == "back" ? GL_BACK : GL_FRONT);
  }
  glFrontFace(GL_CW);  // counter-clockwise in the emulator's rows, mirrored by the y flip
  const std::string blend = draw["blend"];
  if (blend == "opaque") {
    glDisable(GL_BLEND);
  } else {
    glEnable(GL_BLEND);
    if (blend == "alpha") {
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    } else {
      glBlendFunc(GL_ONE, GL_ONE);
    }
  }
  if (draw["depth_test"].get<bool>() || draw["depth_write"].get<bool>()) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(draw["depth_test"].get<bool>() ? GL_LESS : GL_ALWAYS);
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  glDepthMask(draw["depth_write"].get<bool>() ? GL_TRUE : GL_FALSE);
}

// What the replay read back, as float RGBA (a depth-only pass: depth in every channel).
std::vector<float> read_back(const Target& t) {
  const std::size_t n = static_cast<std::size_t>(t.width) * t.height;
  std::vector<float> out(n * 4);
  if (t.format.type == GL_UNSIGNED_BYTE) {
    std::vector<std::uint8_t> bytes(n * 4);
    glReadPixels(0, 0, t.width, t.height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    for (std::size_t i = 0; i < bytes.size(); ++i) out[i] = bytes[i] / 255.0f;
  } else {
    glReadPixels(0, 0, t.width, t.height, GL_RGBA, GL_FLOAT, out.data());
  }
  check_gl("reading the target back");
  return out;
}

// The emulator's target from the export, as float RGBA.
std::vector<float> emulated(Files& files, const json& data) {
  const std::string& blob = files.get(data["file"]);
  const std::size_t n =
      static_cast<std::size_t>(data["size"][0].get<int>()) * data["size"][1].get<int>();
  std::vector<float> out(n * 4);
  const std::string encoding = data["encoding"];
  if (encoding == "rgba8") {
    for (std::size_t i = 0; i < n * 4; ++i) {
      out[i] = static_cast<std::uint8_t>(blob[i]) / 255.0f;
    }
  } else if (encoding == "r32f") {
    for (std::size_t i = 0; i < n; ++i) {
      float d = 0.0f;
      std::memcpy(&d, blob.data() + i * 4, 4);
      std::fill_n(&out[i * 4], 4, d);
    }
  } else {
    std::memcpy(out.data(), blob.data(), n * 16);
  }
  return out;
}

// A float RGBA image as an 8-bit binary PPM (rgb clamped to [0, 1] of `peak`), to look at.
void write_ppm(const fs::path& path, const std::vector<float>& rgba, int w, int h, float peak) {
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << w << " " << h << "\n255\n";
  for (std::size_t p = 0; p < static_cast<std::size_t>(w) * h; ++p) {
    for (int c = 0; c < 3; ++c) {
      const float v = std::clamp(rgba[p * 4 + c] / peak, 0.0f, 1.0f);
      out.put(static_cast<char>(std::lround(v * 255.0f)));
    }
  }
}

// Replays passes on the current context, caching programs, meshes and textures.
class Replay {
 public:
  Replay(const fs::path& dir, fs::path images)
      : files_(dir), programs_(dir), images_(std::move(images)) {}

  // Renders `pass` from its inputs (and `before`, the target's earlier contents). With
  // `compare`, reads the target back and compares it with the emulator's; `ms` gets the wall
  // time of the pass's clear and draws, each end bracketed by glFinish.
  json run(const json& pass, const json* before, bool compare, double& ms) {
    if (pass.value("samples", 1) > 1) {
      fail(fmt::format("pass '{}' is multisampled ({} samples); the replay draws 1x only",
                       pass["name"].get<std::string>(), pass["samples"].get<int>()));
    }
    const Target t = make_target(files_, pass, before);
    glViewport(0, 0, t.width, t.height);
    if (pass.contains("render_area")) {
      const json& r = pass["render_area"];
      glEnable(GL_SCISSOR_TEST);
      glScissor(r[0], r[1], r[2].get<int>() - r[0].get<int>(), r[3].get<int>() - r[1].get<int>());
    } else {
      glDisable(GL_SCISSOR_TEST);
    }
    GLbitfield clear = GL_DEPTH_BUFFER_BIT;
    if (pass["color"].is_null()) {
      glClearColor(1.0f, 1.0f, 1.0f, 1.0f);  // no fragment: the cleared depth, 1
      clear |= GL_COLOR_BUFFER_BIT;
    } else if (pass["color"]["load"] == "clear") {
      const json& c = pass["color"]["clear"];
      glClearColor(c[0], c[1], c[2], c[3]);
      clear |= GL_COLOR_BUFFER_BIT;
    }
    glDepthMask(GL_TRUE);
    glClearDepthf(1.0f);
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glFinish();  // the target's allocation and contents are not the pass's work
    const auto start = std::chrono::steady_clock::now();
    glClear(clear);
    for (const json& draw : pass["draws"]) this->draw(pass, draw);
    glFinish();
    ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    glDeleteVertexArrays(1, &vao);
    json result = json::object();
    if (compare) result = compare_with_emulator(pass, t);
    glDeleteFramebuffers(1, &t.framebuffer);
    glDeleteRenderbuffers(1, &t.depth);
    glDeleteTextures(1, &t.texture);
    return result;
  }

 private:
  void draw(const json& pass, const json& draw) {
    const GLuint program = programs_.get(draw["vertex_shader"], draw["fragment_shader"]);
    glUseProgram(program);
    const json& geometry = draw["geometry"]["data"];
    const std::string mesh_key = geometry["file"];
    if (!meshes_.count(mesh_key)) meshes_[mesh_key] = upload_mesh(files_, geometry);
    const Mesh& mesh = meshes_[mesh_key];
    glBindBuffer(GL_ARRAY_BUFFER, mesh.buffer);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh.indices);
    for (GLuint a = 0; a < 8; ++a) glDisableVertexAttribArray(a);
    for (const auto& [name, layout] : geometry["attributes"].items()) {
      const GLint location = glGetAttribLocation(program, name.c_str());
      if (location < 0) continue;
      glEnableVertexAttribArray(static_cast<GLuint>(location));
      glVertexAttribPointer(static_cast<GLuint>(location), layout["components"], GL_FLOAT, GL_FALSE,
                            0, reinterpret_cast<const void*>(layout["offset"].get<std::size_t>()));
    }
    for (const json& binding : draw["textures"]) {
      const std::string key = binding["data"]["file"].get<std::string>() + "|" +
                              binding["sampler_state"].dump() + binding["type"].get<std::string>();
      const int unit = binding["binding"];
      glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));  // before an upload binds
      if (!textures_.count(key)) textures_[key] = upload_binding(files_, binding);
      glBindTexture(binding["type"] == "cube" ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D,
                    textures_[key]);
      glUniform1i(glGetUniformLocation(program, binding["sampler"].get<std::string>().c_str()),
                  unit);
    }
    if (draw["uniforms"].contains("u_inv_target_size")) {
      const json& v = draw["uniforms"]["u_inv_target_size"];
      glUniform2f(glGetUniformLocation(program, "u_inv_target_size"), v[0], v[1]);
    }
    set_state(draw);
    glDrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
    check_gl(fmt::format("pass {} draw {}", pass["name"].get<std::string>(),
                         draw["vertex_shader"].get<std::string>()));
  }

  json compare_with_emulator(const json& pass, const Target& t) {
    const std::vector<float> replayed = read_back(t);
    const json& reference = pass["color"].is_null() ? pass["depth"]["data"] : pass["color"]["data"];
    const std::vector<float> expected = emulated(files_, reference);
    json result = skinsim::crosscheck::compare_targets(expected, replayed, t.width, t.height,
                                                       pass["color"].is_null());
    result["pass"] = pass["name"];
    if (!images_.empty()) {
      const std::string stem =
          fmt::format("{}_{}", images_written_++, pass["name"].get<std::string>());
      const float peak = result["peak"];
      write_ppm(images_ / (stem + "_emulated.ppm"), expected, t.width, t.height, peak);
      write_ppm(images_ / (stem + "_llvmpipe.ppm"), replayed, t.width, t.height, peak);
    }
    return result;
  }

  Files files_;
  Programs programs_;
  fs::path images_;
  int images_written_ = 0;
  std::map<std::string, GLuint> textures_;
  std::map<std::string, Mesh> meshes_;
};

struct Options {
  fs::path dir, result, images;
  int time_rounds = 0;
};

Options parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) fail("option " + arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--result") {
      o.result = value();
    } else if (arg == "--images") {
      o.images = value();
    } else if (arg == "--time") {
      const std::string v = value();
      char* end = nullptr;
      const long rounds = std::strtol(v.c_str(), &end, 10);
      if (v.empty() || *end != '\0' || rounds < 1 || rounds > 1000) {
        fail("--time must be a whole number of rounds in [1, 1000], got '" + v + "'");
      }
      o.time_rounds = static_cast<int>(rounds);
    } else if (o.dir.empty() && !arg.starts_with("--")) {
      o.dir = arg;
    } else {
      fail("unknown argument '" + arg + "'");
    }
  }
  if (o.dir.empty()) fail("no export directory given");
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  try {
    o = parse_options(argc, argv);
  } catch (const std::exception& e) {
    fmt::print(stderr,
               "gles_replay: {}\n"
               "usage: gles_replay EXPORT_DIR [--result FILE.json] [--images DIR] [--time ROUNDS]\n"
               "  EXPORT_DIR from: skinsim export --glsl es300 --data --out EXPORT_DIR\n"
               "  --images: each pass's target, emulated and replayed, as PPM\n"
               "  --time: replay the frame ROUNDS more times and print its median time\n",
               e.what());
    return 2;
  }
  try {
    const json frame = json::parse(read_file(o.dir / "frame.json"));
    if (frame["glsl"] != "es300") fail("the export must be --glsl es300 (an OpenGL ES 3.0 replay)");
    if (!o.images.empty()) fs::create_directories(o.images);
    SurfacelessContext context;
    fmt::print("{} on {}: {}\n", frame["technique"].get<std::string>(),
               reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
               reinterpret_cast<const char*>(glGetString(GL_VERSION)));
    Replay replay(o.dir, o.images);
    // Each pass with the emulator's contents of its target before it, where there were any.
    std::vector<const json*> before;
    std::map<std::string, const json*> last_contents;
    for (const json& pass : frame["passes"]) {
      const json* b = nullptr;
      if (!pass["color"].is_null()) {
        const auto it = last_contents.find(pass["color"]["target"]);
        if (it != last_contents.end()) b = it->second;
        last_contents[pass["color"]["target"]] = &pass["color"]["data"];
      }
      before.push_back(b);
    }
    json results = json::array();
    double ms = 0.0;
    for (std::size_t p = 0; p < frame["passes"].size(); ++p) {
      results.push_back(replay.run(frame["passes"][p], before[p], true, ms));
      fmt::print("{}\n", skinsim::crosscheck::format_row(results.back()));
    }
    json out = {{"technique", frame["technique"]}, {"passes", results}};
    if (o.time_rounds > 0) {  // the first round compiled the shaders and uploaded the data
      std::vector<double> frames;
      for (int r = 0; r < o.time_rounds; ++r) {
        double total = 0.0;
        for (std::size_t p = 0; p < frame["passes"].size(); ++p) {
          replay.run(frame["passes"][p], before[p], false, ms);
          total += ms;
        }
        frames.push_back(total);
      }
      std::sort(frames.begin(), frames.end());
      const double median = frames[frames.size() / 2];
      fmt::print(
          "llvmpipe frame: {:.1f} ms median of {} (each pass's clear and draws, glFinish "
          "at both ends)\n",
          median, frames.size());
      out["frame_ms_median"] = median;
    }
    if (!o.result.empty()) std::ofstream(o.result) << out.dump(2) << "\n";
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "gles_replay: {}\n", e.what());
    return 2;
  }
}
