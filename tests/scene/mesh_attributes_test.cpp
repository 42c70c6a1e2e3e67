#include "scene/mesh_attributes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace skinsim::scene {
namespace {

TEST(SmoothNormals, AreaWeightedAndWeldedAcrossSplitVertices) {
  // Two triangles meeting at a ridge along the x axis: one tilted towards +Y (large),
  // one towards -Y (small). The ridge vertices are duplicated (split) for the second one.
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0},  {0, 2, 1},   // big, normal (0,-1,2)/|.|
                                    {0, 0, 0}, {0, -1, 1}, {1, 0, 0}};  // small
  const std::vector<std::uint32_t> idx = {0, 1, 2, 3, 4, 5};
  const auto n = compute_smooth_normals(p, idx);
  const glm::vec3 big = glm::cross(p[1] - p[0], p[2] - p[0]);
  const glm::vec3 small = glm::cross(p[4] - p[3], p[5] - p[3]);
  const glm::vec3 expected = glm::normalize(big + small);
  for (int i : {0, 1, 3, 5}) {  // ridge vertices: welded, area-weighted sum
    EXPECT_NEAR(glm::dot(n[i], expected), 1.0f, 1e-6f) << i;
  }
  EXPECT_NEAR(glm::dot(n[2], glm::normalize(big)), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(n[4], glm::normalize(small)), 1.0f, 1e-6f);
}

TEST(SmoothNormals, UnusedVertexGetsPlusZ) {
  const auto n = compute_smooth_normals({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}}, {0, 1, 2});
  EXPECT_EQ(n[3], glm::vec3(0, 0, 1));
}

TEST(Tangents, FollowUAndEncodeHandedness) {
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<glm::vec3> n(3, glm::vec3(0, 0, 1));
  const std::vector<std::uint32_t> idx = {0, 1, 2};
  // glTF UVs, v down: +y on the surface is "up" in the image, so B = cross(N, T) and w = +1.
  auto t = compute_tangents(p, n, {{0, 1}, {1, 1}, {0, 0}}, idx);
  for (const auto& v : t) {
    EXPECT_NEAR(v.x, 1.0f, 1e-6f);
    EXPECT_EQ(v.w, 1.0f);
  }
  // v up instead (image flipped vertically): same T, mirrored bitangent, w = -1.
  t = compute_tangents(p, n, {{0, 0}, {1, 0}, {0, 1}}, idx);
  for (const auto& v : t) {
    EXPECT_NEAR(v.x, 1.0f, 1e-6f);
    EXPECT_EQ(v.w, -1.0f);
  }
  // u runs along -x: T = -X.
  t = compute_tangents(p, n, {{1, 1}, {0, 1}, {1, 0}}, idx);
  EXPECT_NEAR(t[0].x, -1.0f, 1e-6f);
}

TEST(Tangents, GramSchmidtAgainstTheVertexNormal) {
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const glm::vec3 tilted = glm::normalize(glm::vec3(1, 0, 1));
  const auto t = compute_tangents(p, {tilted, tilted, tilted}, {{0, 1}, {1, 1}, {0, 0}}, {0, 1, 2});
  for (const auto& v : t) {
    EXPECT_NEAR(glm::dot(glm::vec3(v), tilted), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(glm::vec3(v)), 1.0f, 1e-6f);
  }
}

TEST(Tangents, DegenerateUvsFallBackToAnOrthogonalUnitVector) {
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const glm::vec3 nz(0, 0, 1);
  const auto t = compute_tangents(p, {nz, nz, nz}, {{0, 0}, {0, 0}, {0, 0}}, {0, 1, 2});
  for (const auto& v : t) {
    EXPECT_NEAR(glm::dot(glm::vec3(v), nz), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(glm::vec3(v)), 1.0f, 1e-6f);
  }
}

TEST(AnyOrthogonal, IsUnitAndOrthogonalEverywhere) {
  for (const glm::vec3 n :
       {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 0, 0),
        glm::normalize(glm::vec3(1, -2, 3)), glm::normalize(glm::vec3(0, 1e-7f, -1))}) {
    const glm::vec3 t = any_orthogonal(n);
    EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-6f);
  }
}

}  // namespace
}  // namespace skinsim::scene
