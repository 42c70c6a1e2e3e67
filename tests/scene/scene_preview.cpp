// Writes the default scene's textures, its environment and Lambert previews of the default
// scene (and of a glTF file, if given) as PNGs, for looking at them:
//   scene_preview <out_dir> [file.gltf|file.glb]
#include <cmath>
#include <cstdio>
#include <string>

#include "image/image.h"
#include "scene/gltf_loader.h"
#include "scene/procedural_head.h"
#include "tests/scene/preview_raster.h"

namespace {

using skinsim::scene::Image;

void write_png(const std::string& path, int w, int h, int channels,
               const std::vector<float>& data) {
  std::vector<std::uint8_t> bytes(data.size());
  for (std::size_t i = 0; i < data.size(); ++i) {
    bytes[i] = static_cast<std::uint8_t>(std::lround(std::clamp(data[i], 0.0f, 1.0f) * 255.0f));
  }
  skinsim::image::write_png_u8(path, w, h, channels, bytes);
  std::printf("wrote %s\n", path.c_str());
}

void write_image(const std::string& path, const Image& img, bool alpha_only) {
  std::vector<float> d;
  for (const auto& t : img.texels) {
    if (alpha_only) {
      d.push_back(t.a);
    } else {
      d.insert(d.end(), {t.r, t.g, t.b});
    }
  }
  write_png(path, img.width, img.height, alpha_only ? 1 : 3, d);
}

void write_render(const std::string& path, const skinsim::scene::Scene& s) {
  const auto f = skinsim::scene::testing::rasterize(s, 1024, 768);
  std::vector<float> d;
  for (const auto& c : f.color) {
    for (int k = 0; k < 3; ++k) d.push_back(std::pow(std::max(c[k], 0.0f), 1.0f / 2.2f));
  }
  write_png(path, f.width, f.height, 3, d);
  std::printf("  skin coverage %.3f\n", coverage(s, f, skinsim::scene::MaterialKind::kSkin));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s <out_dir> [file.gltf|file.glb]\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  const auto s = skinsim::scene::make_default_scene({});
  write_image(dir + "/skin_albedo.png", s.images[0], false);
  write_image(dir + "/skin_reflectivity.png", s.images[0], true);
  write_image(dir + "/skin_normal.png", s.images[1], false);
  write_image(dir + "/eye_albedo.png", s.images[2], false);
  // Environment as a horizontal strip of the six faces, Reinhard tone mapped.
  const int n = s.environment.size;
  std::vector<float> env;
  for (int y = 0; y < n; ++y) {
    for (int f = 0; f < 6; ++f) {
      for (int x = 0; x < n; ++x) {
        const auto& t = s.environment.faces[f][static_cast<std::size_t>(y) * n + x];
        for (int k = 0; k < 3; ++k) env.push_back(std::pow(t[k] / (1.0f + t[k]), 1.0f / 2.2f));
      }
    }
  }
  write_png(dir + "/environment.png", 6 * n, n, 3, env);
  write_render(dir + "/default_scene.png", s);
  if (argc > 2) {
    skinsim::scene::LoadOptions opts;
    opts.skin_materials = {"all"};
    write_render(dir + "/gltf_scene.png", skinsim::scene::load_gltf(argv[2], opts));
  }
  return 0;
}
