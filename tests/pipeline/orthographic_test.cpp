// A glTF quad that exactly fills the view of its own camera shades exactly W x H fragments,
// orthographic (xmag / ymag half extents, the width following the render aspect) or
// perspective; and the screen-space diffusion runs its orthographic programs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "pipeline/config.h"
#include "pipeline/frame.h"
#include "pipeline/gpu_scene.h"
#include "scene/gltf_loader.h"
#include "sim/gpu.h"
#include "tests/scene/gltf_fixture.h"

namespace skinsim::pipeline {
namespace {

struct FillCase {
  const char* name;
  bool orthographic;
  int width;
  int height;
};

// A skin quad at z = -1 spanning y in [-1, 1] and x in [-aspect, aspect], seen by a camera
// at the origin looking down -Z: orthographic with ymag 1 (xmag 1: the render aspect
// wins), or perspective with a 90 degree vertical field of view.
scene::Scene filling_quad(const FillCase& c) {
  scene::testing::GltfFixture f(std::string("ortho_fill_") + c.name);
  f.add_quad_mesh(true, true);
  const double aspect = static_cast<double>(c.width) / c.height;
  f.json()["nodes"][0]["scale"] = {2.0 * aspect, 2.0, 1.0};
  f.json()["nodes"][0]["translation"] = {-aspect, -1.0, -1.0};
  f.json()["materials"] = {{{"name", "skin"}}};
  f.json()["meshes"][0]["primitives"][0]["material"] = 0;
  if (c.orthographic) {
    f.json()["cameras"] = {
        {{"type", "orthographic"},
         {"orthographic", {{"xmag", 1.0}, {"ymag", 1.0}, {"znear", 0.01}, {"zfar", 10.0}}}}};
  } else {
    f.json()["cameras"] = {
        {{"type", "perspective"},
         {"perspective", {{"yfov", std::numbers::pi / 2}, {"znear", 0.01}, {"zfar", 10.0}}}}};
  }
  f.json()["nodes"].push_back({{"camera", 0}});
  f.json()["scenes"][0]["nodes"].push_back(1);
  scene::LoadOptions o;
  o.warn = [](const std::string&) {};
  o.environment_size = 4;
  return scene::load_gltf(f.write_glb("quad"), o);
}

FrameOutput render(const scene::Scene& s, const std::string& technique, const FillCase& c) {
  PipelineConfig config;
  set_config_field(config, "technique", technique);
  set_config_field(config, "resolution", std::to_string(c.width) + "x" + std::to_string(c.height));
  const GpuScene gs(s);
  sim::GpuConfig g;
  g.threads = 2;
  sim::Gpu gpu(g);
  return render_frame(gs, config, gpu);
}

const sim::PassCounters& pass(const FrameOutput& out, const std::string& name) {
  for (const sim::PassCounters& p : out.passes) {
    if (p.name == name) return p;
  }
  throw std::runtime_error("no pass " + name);
}

class FillingQuad : public ::testing::TestWithParam<FillCase> {};

TEST_P(FillingQuad, ShadesEveryPixelOnce) {
  const FillCase& c = GetParam();
  const scene::Scene s = filling_quad(c);
  const FrameOutput out = render(s, "mobile", c);
  ASSERT_EQ(out.decisions.at("lod_shader"), 0.0);
  EXPECT_EQ(out.view.orthographic, c.orthographic);
  const std::uint64_t pixels = static_cast<std::uint64_t>(c.width) * c.height;
  EXPECT_EQ(out.passes.back().fragments_shaded, pixels);
  EXPECT_EQ(out.view.skin_rect.x1 - out.view.skin_rect.x0, c.width);
  EXPECT_EQ(out.view.skin_rect.y1 - out.view.skin_rect.y0, c.height);
  // The skin is 1 unit away: ymag 1 and tan(45 deg) = 1 both give H / 2 pixels per unit.
  EXPECT_NEAR(out.view.pixels_per_mm(s.units_per_mm), 0.5f * c.height * s.units_per_mm, 1e-6f);
}

TEST_P(FillingQuad, ScreenSpaceDiffusionCoversTheView) {
  const FillCase& c = GetParam();
  const FrameOutput out = render(filling_quad(c), "burley", c);
  const std::uint64_t pixels = static_cast<std::uint64_t>(c.width) * c.height;
  EXPECT_EQ(pass(out, "diffuse").fragments_shaded, pixels);
  const sim::PassCounters& sss = pass(out, "sss");
  EXPECT_EQ(sss.fragments_shaded, pixels);
  ASSERT_EQ(sss.draws.size(), 1u);
  EXPECT_EQ(sss.draws[0].fragment_program,
            c.orthographic ? "burley_sss_ortho_fs" : "burley_sss_fs");
  // Orthographic: parallel view vectors and one depth on a quad facing the camera, so
  // diffusion and specular are the same at every pixel (perspective: the view vector turns).
  const glm::vec4 corner = out.frame.at(0, 0), centre = out.frame.at(c.width / 2, c.height / 2);
  EXPECT_GT(centre.r, 0.05f);
  if (c.orthographic) {
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(corner[ch], centre[ch], 1.5f / 255.0f) << ch;
  }
}

TEST_P(FillingQuad, UrpAoOfAQuadFacingTheCameraIsOne) {
  const FillCase& c = GetParam();
  const FrameOutput out = render(filling_quad(c), "urp", c);
  EXPECT_EQ(pass(out, "ssao").draws.at(0).fragment_program,
            c.orthographic ? "ssao_ortho_fs" : "ssao_fs");
  const auto ao = std::find_if(out.intermediates.begin(), out.intermediates.end(),
                               [](const NamedTarget& t) { return t.name == "ssao"; });
  ASSERT_NE(ao, out.intermediates.end());
  for (const glm::vec4& p : ao->target.pixels) ASSERT_EQ(p.r, 1.0f);
}

INSTANTIATE_TEST_SUITE_P(Cases, FillingQuad,
                         ::testing::Values(FillCase{"ortho_64x64", true, 64, 64},
                                           FillCase{"ortho_64x48", true, 64, 48},
                                           FillCase{"perspective_64x64", false, 64, 64},
                                           FillCase{"perspective_64x48", false, 64, 48}),
                         [](const auto& test) { return std::string(test.param.name); });

}  // namespace
}  // namespace skinsim::pipeline
