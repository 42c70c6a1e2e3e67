#include "driver/frame/frame_export_data.h"

#include <fmt/format.h>

#include <bit>
#include <vector>

#include "util/unorm8.h"

namespace skinsim::driver {

namespace {

template <typename T>
void append(std::string& out, const T* values, std::size_t count) {
  static_assert(std::endian::native == std::endian::little);
  out.append(reinterpret_cast<const char*>(values), count * sizeof(T));
}

// One level's texels: RGBA8 as bytes (exact: stored values are multiples of 1/255), depth as
// one float32, others as four.
void append_texels(std::string& out, const glm::vec4* texels, std::size_t count,
                   sim::TexelFormat format) {
  if (sim::is_depth_format(format)) {
    for (std::size_t i = 0; i < count; ++i) append(out, &texels[i].x, 1);
    return;
  }
  if (format != sim::TexelFormat::kRGBA8) {
    append(out, &texels[0].x, count * 4);
    return;
  }
  std::vector<std::uint8_t> bytes(count * 4);
  for (std::size_t i = 0; i < count; ++i) {
    for (int c = 0; c < 4; ++c) {
      bytes[i * 4 + c] = unorm8_nearest(texels[i][c]);
    }
  }
  append(out, bytes.data(), bytes.size());
}

const char* encoding(sim::TexelFormat format) {
  if (sim::is_depth_format(format)) return "r32f";
  return format == sim::TexelFormat::kRGBA8 ? "rgba8" : "rgba32f";
}

nlohmann::json levels(std::string& out, const sim::Texture2D& t) {
  nlohmann::json j = nlohmann::json::array();
  for (int l = 0; l < t.level_count(); ++l) {
    const sim::LevelView& level = t.level(l);
    j.push_back({{"size", {level.width, level.height}}, {"offset", out.size()}});
    append_texels(out, level.texels, static_cast<std::size_t>(level.width) * level.height,
                  t.format());
  }
  return j;
}

}  // namespace

nlohmann::json ExportData::geometry(const sim::Geometry& g) {
  const std::pair<const void*, const void*> key{g.attributes.positions, g.indices};
  const auto known = written_.find(key);
  if (known != written_.end()) return known->second;
  const std::string file = fmt::format("data/geometry_{}.bin", written_.size());
  std::string out;
  const std::size_t n = g.vertex_count;
  // Every attribute, with the value ExecVertexIn gives where the mesh has none.
  nlohmann::json attributes = nlohmann::json::object();
  const auto add = [&](const char* name, int components, auto&& value) {
    attributes[name] = {{"offset", out.size()}, {"components", components}};
    for (std::size_t v = 0; v < n; ++v) {
      const sim::ExecVertexIn in(g.attributes, static_cast<std::uint32_t>(v));
      const auto x = value(in);
      if constexpr (std::is_same_v<decltype(x), const float>) {
        append(out, &x, 1);
      } else {
        append(out, &x[0], static_cast<std::size_t>(components));
      }
    }
  };
  add("a_position", 3, [](const sim::ExecVertexIn& in) { return in.position(); });
  add("a_normal", 3, [](const sim::ExecVertexIn& in) { return in.normal(); });
  add("a_uv", 2, [](const sim::ExecVertexIn& in) { return in.uv(); });
  add("a_tangent", 4, [](const sim::ExecVertexIn& in) { return in.tangent(); });
  add("a_thickness", 1, [](const sim::ExecVertexIn& in) { return in.thickness(); });
  const std::size_t indices_offset = out.size();
  append(out, g.indices, g.index_count);  // the emulator draws indexed triangles only
  (*files_)[file] = std::move(out);
  nlohmann::json j = {{"file", file},
                      {"attributes", std::move(attributes)},
                      {"indices", {{"offset", indices_offset}, {"count", g.index_count}}}};
  return written_[key] = j;
}

nlohmann::json ExportData::texture(const sim::Texture2D& t) {
  const auto known = written_.find({&t, nullptr});
  if (known != written_.end()) return known->second;
  const std::string file = fmt::format("data/texture_{}.bin", written_.size());
  std::string out;
  nlohmann::json j = {{"file", file}, {"encoding", encoding(t.format())}};
  j["levels"] = levels(out, t);
  (*files_)[file] = std::move(out);
  return written_[{&t, nullptr}] = j;
}

nlohmann::json ExportData::cube(const sim::TextureCube& c) {
  const auto known = written_.find({&c, nullptr});
  if (known != written_.end()) return known->second;
  const std::string file = fmt::format("data/cube_{}.bin", written_.size());
  std::string out;
  nlohmann::json faces = nlohmann::json::array();
  for (int f = 0; f < 6; ++f) faces.push_back(levels(out, c.face(f)));
  (*files_)[file] = std::move(out);
  nlohmann::json j = {
      {"file", file}, {"encoding", encoding(c.format())}, {"faces", std::move(faces)}};
  return written_[{&c, nullptr}] = j;
}

nlohmann::json ExportData::target(const sim::RenderTarget& t, const std::string& file_stem) {
  const std::string file = "data/" + file_stem + ".bin";
  std::string out;
  append_texels(out, t.pixels.data(), t.pixels.size(), t.format);
  (*files_)[file] = std::move(out);
  return {{"file", file}, {"encoding", encoding(t.format)}, {"size", {t.width, t.height}}};
}

}  // namespace skinsim::driver
