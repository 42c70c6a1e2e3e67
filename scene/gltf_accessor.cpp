#include "scene/gltf_accessor.h"

#include <fmt/format.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>

#include "scene/error.h"

namespace skinsim::scene::gltf {
namespace {

int component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

const char* component_name(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return "FLOAT";
    default:
      return "an invalid component type";
  }
}

int type_components(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    default:
      return 0;  // matrices are never vertex attributes we read
  }
}

// A validated strided run of `count` elements of `elem_size` bytes.
struct Span {
  const unsigned char* data = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
};

Span locate(const tinygltf::Model& model, int view_index, std::size_t byte_offset,
            std::size_t count, std::size_t elem_size, bool allow_stride, const std::string& file,
            const std::string& where) {
  std::size_t view_size = 0;
  const unsigned char* bytes = buffer_view_bytes(model, view_index, &view_size, file, where);
  const auto& view = model.bufferViews[static_cast<std::size_t>(view_index)];
  const std::size_t stride = allow_stride && view.byteStride != 0 ? view.byteStride : elem_size;
  if (stride < elem_size) {
    throw SceneError(
        fmt::format("{}: {}: bufferViews[{}].byteStride {} is smaller than the {}-byte element",
                    file, where, view_index, stride, elem_size));
  }
  // count <= view_size keeps (count - 1) * stride far from overflow.
  if (count == 0 || count > view_size || byte_offset > view_size ||
      (count - 1) * stride + elem_size > view_size - byte_offset) {
    throw SceneError(fmt::format(
        "{}: {}: {} elements of {} bytes (stride {}) at byteOffset {} do not fit bufferViews[{}] "
        "of {} bytes",
        file, where, count, elem_size, stride, byte_offset, view_index, view_size));
  }
  return {bytes + byte_offset, stride, count};
}

float component_as_float(const unsigned char* p, int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f;
      std::memcpy(&f, p, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return p[0] / 255.0f;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return v / 65535.0f;
    }
    default:
      return 0.0f;  // excluded by check_format
  }
}

std::uint32_t component_as_uint(const unsigned char* p, int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return p[0];
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    default: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

const tinygltf::Accessor& accessor_at(const tinygltf::Model& model, int index,
                                      const std::string& file, const std::string& where) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
    throw SceneError(fmt::format("{}: {}: accessor index {} out of range ({} accessors)", file,
                                 where, index, model.accessors.size()));
  }
  return model.accessors[static_cast<std::size_t>(index)];
}

void check_format(const tinygltf::Accessor& a, int components, AttributeFormat format,
                  const std::string& file, const std::string& where) {
  if (type_components(a.type) != components) {
    throw SceneError(fmt::format("{}: {}: accessor type must have {} components, got type {}", file,
                                 where, components, a.type));
  }
  const bool is_float = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
  const bool is_unorm = a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                         a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  if (!(is_float || (format == AttributeFormat::kFloatOrNormalized && is_unorm))) {
    throw SceneError(fmt::format(
        "{}: {}: componentType {}{} is not allowed here (expected {})", file, where,
        component_name(a.componentType), a.normalized ? " (normalized)" : "",
        format == AttributeFormat::kFloatOnly ? "FLOAT"
                                              : "FLOAT or normalized UNSIGNED_BYTE/SHORT"));
  }
}

// Sparse substitution (spec 3.6.2.3): indices and replacement values for some elements.
template <typename T, typename Convert>
void apply_sparse(const tinygltf::Model& model, const tinygltf::Accessor& a, int components,
                  std::vector<T>& out, Convert convert, const std::string& file,
                  const std::string& where) {
  const auto& sp = a.sparse;
  if (sp.count <= 0 || static_cast<std::size_t>(sp.count) > a.count) {
    throw SceneError(
        fmt::format("{}: {}: sparse.count {} must be in [1, {}]", file, where, sp.count, a.count));
  }
  const int index_type = sp.indices.componentType;
  if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
    throw SceneError(fmt::format("{}: {}: sparse.indices.componentType must be unsigned, got {}",
                                 file, where, component_name(index_type)));
  }
  const std::size_t n = static_cast<std::size_t>(sp.count);
  if (sp.indices.byteOffset < 0 || sp.values.byteOffset < 0) {
    throw SceneError(fmt::format("{}: {}: negative sparse byteOffset", file, where));
  }
  const Span idx = locate(
      model, sp.indices.bufferView, static_cast<std::size_t>(sp.indices.byteOffset), n,
      static_cast<std::size_t>(component_size(index_type)), false, file, where + ".sparse.indices");
  const std::size_t csize = static_cast<std::size_t>(component_size(a.componentType));
  const Span val =
      locate(model, sp.values.bufferView, static_cast<std::size_t>(sp.values.byteOffset), n,
             csize * components, false, file, where + ".sparse.values");
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t target = component_as_uint(idx.data + i * idx.stride, index_type);
    if (target >= a.count) {
      throw SceneError(fmt::format("{}: {}: sparse index {} out of range of {} elements", file,
                                   where, target, a.count));
    }
    for (int c = 0; c < components; ++c) {
      out[static_cast<std::size_t>(target) * components + c] =
          convert(val.data + i * val.stride + c * csize);
    }
  }
}

}  // namespace

const unsigned char* buffer_view_bytes(const tinygltf::Model& model, int view_index,
                                       std::size_t* size, const std::string& file,
                                       const std::string& where) {
  if (view_index < 0 || static_cast<std::size_t>(view_index) >= model.bufferViews.size()) {
    throw SceneError(fmt::format("{}: {}: bufferView index {} out of range ({} bufferViews)", file,
                                 where, view_index, model.bufferViews.size()));
  }
  const auto& view = model.bufferViews[static_cast<std::size_t>(view_index)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
    throw SceneError(fmt::format("{}: {}: bufferViews[{}].buffer {} out of range ({} buffers)",
                                 file, where, view_index, view.buffer, model.buffers.size()));
  }
  const auto& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
    throw SceneError(fmt::format(
        "{}: {}: bufferViews[{}] (byteOffset {}, byteLength {}) exceeds buffers[{}], which "
        "holds {} bytes",
        file, where, view_index, view.byteOffset, view.byteLength, view.buffer, data.size()));
  }
  *size = view.byteLength;
  return data.data() + view.byteOffset;
}

std::vector<float> read_floats(const tinygltf::Model& model, int index, int components,
                               AttributeFormat format, const std::string& file,
                               const std::string& where_field) {
  const std::string where = fmt::format("{} (accessors[{}])", where_field, index);
  const tinygltf::Accessor& a = accessor_at(model, index, file, where);
  check_format(a, components, format, file, where);
  if (a.count == 0) throw SceneError(fmt::format("{}: {}: count is 0", file, where));
  const std::size_t csize = static_cast<std::size_t>(component_size(a.componentType));
  auto convert = [&](const unsigned char* p) { return component_as_float(p, a.componentType); };
  std::vector<float> out;
  if (a.bufferView < 0) {
    // No bufferView: all zeros, unless sparse substitution follows (spec 3.6.2.3).
    // Cap the zeros at what the file's largest buffer could hold, so a few bytes of JSON
    // cannot demand gigabytes.
    std::size_t largest = 0;
    for (const auto& b : model.buffers) largest = std::max(largest, b.data.size());
    const std::size_t limit = largest / (csize * components);
    if (a.count > limit) {
      throw SceneError(fmt::format(
          "{}: {}: count {} without a bufferView exceeds the {} elements the largest buffer "
          "({} bytes) could hold",
          file, where, a.count, limit, largest));
    }
    out.assign(a.count * components, 0.0f);
  } else {
    const Span s =
        locate(model, a.bufferView, a.byteOffset, a.count, csize * components, true, file, where);
    out.resize(a.count * components);
    for (std::size_t i = 0; i < s.count; ++i) {
      for (int c = 0; c < components; ++c)
        out[i * components + c] = convert(s.data + i * s.stride + c * csize);
    }
  }
  if (a.sparse.isSparse) apply_sparse(model, a, components, out, convert, file, where);
  return out;
}

std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, int index,
                                        const std::string& file, const std::string& where_field) {
  const std::string where = fmt::format("{} (accessors[{}])", where_field, index);
  const tinygltf::Accessor& a = accessor_at(model, index, file, where);
  if (a.type != TINYGLTF_TYPE_SCALAR) {
    throw SceneError(fmt::format("{}: {}: index accessor type must be SCALAR", file, where));
  }
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
    throw SceneError(
        fmt::format("{}: {}: index componentType must be UNSIGNED_BYTE/SHORT/INT, got {}", file,
                    where, component_name(a.componentType)));
  }
  if (a.bufferView < 0 || a.sparse.isSparse) {
    throw SceneError(fmt::format("{}: {}: index accessors need a bufferView and may not be sparse",
                                 file, where));
  }
  const std::size_t csize = static_cast<std::size_t>(component_size(a.componentType));
  // Indices are tightly packed: byteStride must not be defined for them (spec 3.7.2.1).
  const Span s = locate(model, a.bufferView, a.byteOffset, a.count, csize, false, file, where);
  std::vector<std::uint32_t> out(s.count);
  for (std::size_t i = 0; i < s.count; ++i)
    out[i] = component_as_uint(s.data + i * csize, a.componentType);
  return out;
}

}  // namespace skinsim::scene::gltf
