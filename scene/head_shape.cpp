#include "scene/head_shape.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace skinsim::scene::head {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
// Base ellipsoid semi-axes: an adult head about 0.16 m wide, 0.24 m crown to chin,
// 0.2 m front to back.
constexpr glm::vec3 kAxes(0.079f, 0.118f, 0.098f);
constexpr float kNeckRadiusX = 0.056f;
constexpr float kNeckRadiusZ = 0.058f;
constexpr float kNeckCenterZ = -0.012f;
constexpr float kNeckBottomY = -0.26f;
constexpr float kHeadRows = 0.8f;          // share of v spent on the head; the rest is the neck
constexpr glm::vec2 kEye(0.032f, 0.012f);  // eye centre in the front (x, y) projection
constexpr float kEyeRadius = 0.0125f;

float smoothstep(float e0, float e1, float x) {
  const float t = glm::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// Anisotropic Gaussian bump centred at c with radii s, in the front projection.
float bump(const glm::vec2& p, const glm::vec2& c, const glm::vec2& s) {
  const glm::vec2 d = (p - c) / s;
  return std::exp(-glm::dot(d, d));
}

// A superellipsoid whose exponent grows from 2 below the eyes to 2.6 on the skull, so the
// cranium is fuller and the crown flatter than an ellipsoid's.
float ellipsoid_radius(const glm::vec3& d) {
  const float e = 2.0f + 0.6f * smoothstep(0.0f, 0.6f, d.y);
  const glm::vec3 a = glm::abs(d / kAxes);
  return 1.0f / std::pow(std::pow(a.x, e) + std::pow(a.y, e) + std::pow(a.z, e), 1.0f / e);
}

// Facial relief (metres, along the radial direction) at front-projected point q, for a
// surface direction d. Only the front half gets the face; the sides get the ears.
float relief(const glm::vec3& q, const glm::vec3& d) {
  const float front = smoothstep(0.15f, 0.55f, d.z);
  const glm::vec2 p(q.x, q.y);
  const glm::vec2 m(std::abs(q.x), q.y);  // mirrored: one bump serves both sides
  float h = 0.0f;
  h += 0.006f * bump(m, {0.030f, 0.036f}, {0.030f, 0.010f});  // brow ridges
  h -= 0.014f * bump(m, kEye, {0.017f, 0.012f});              // eye sockets
  // Nose: a ridge from the bridge to the tip, then tip, alae (wings).
  const float ridge = smoothstep(0.022f, -0.032f, q.y) * (1.0f - smoothstep(-0.036f, -0.048f, q.y));
  h += 0.022f * ridge * std::exp(-(q.x * q.x) / (0.010f * 0.010f));
  h += 0.006f * bump(p, {0.0f, -0.035f}, {0.012f, 0.010f});
  h += 0.006f * bump(m, {0.014f, -0.041f}, {0.008f, 0.007f});
  h += 0.007f * bump(m, {0.046f, -0.016f}, {0.022f, 0.020f});  // cheekbones
  h -= 0.004f * bump(m, {0.044f, -0.056f}, {0.018f, 0.020f});  // hollows under them
  h += 0.006f * bump(p, {0.0f, -0.063f}, {0.022f, 0.005f});    // upper lip
  h += 0.006f * bump(p, {0.0f, -0.074f}, {0.019f, 0.006f});    // lower lip
  h -= 0.003f * bump(p, {0.0f, -0.068f}, {0.024f, 0.0015f});   // mouth line
  h += 0.011f * bump(p, {0.0f, -0.100f}, {0.021f, 0.016f});    // chin
  h *= front;
  // Ears: flat lobes on the sides, a little behind the centre.
  const float side = smoothstep(0.75f, 0.92f, std::abs(d.x));
  h += 0.016f * side *
       std::exp(-std::pow((q.y + 0.002f) / 0.026f, 2.0f) - std::pow((q.z + 0.014f) / 0.012f, 2.0f));
  return h;
}

glm::vec3 head_point(float theta, float phi) {
  const glm::vec3 d(std::sin(theta) * std::sin(phi), std::cos(theta),
                    std::sin(theta) * std::cos(phi));
  const glm::vec3 q = d * ellipsoid_radius(d);
  glm::vec3 p = d * (glm::length(q) + relief(q, d));
  // Narrow the jaw towards the chin and pull the lower face forward a little.
  const float lower = smoothstep(-0.01f, -0.11f, p.y);
  p.x *= 1.0f - 0.30f * lower;
  p.z += 0.008f * lower * smoothstep(0.0f, 0.6f, d.z);
  return p;
}

// Polar angle where the head part ends and the neck starts: under the chin at the front,
// at the nape at the back.
float neck_theta(float phi) {
  return kPi * (0.80f + 0.10f * std::cos(phi));
}

}  // namespace

glm::vec3 surface_point(float u, float v) {
  const float phi = (u - 0.5f) * 2.0f * kPi;
  const float theta_end = neck_theta(phi);
  if (v <= kHeadRows) return head_point(theta_end * v / kHeadRows, phi);
  // Neck: from the head's last ring, ease into an elliptic cylinder going straight down.
  const glm::vec3 ring = head_point(theta_end, phi);
  const float t = (v - kHeadRows) / (1.0f - kHeadRows);
  const float y = ring.y + (kNeckBottomY - ring.y) * t;
  const glm::vec3 tube(kNeckRadiusX * std::sin(phi), y,
                       kNeckCenterZ + kNeckRadiusZ * std::cos(phi));
  const float blend = smoothstep(0.0f, 0.35f, t);
  return glm::vec3(glm::mix(ring.x, tube.x, blend), y, glm::mix(ring.z, tube.z, blend));
}

glm::vec3 eye_center(bool right) {
  const float x = right ? kEye.x : -kEye.x;
  // Front of the unrelieved head at the eye, pushed back so the eyeball sits in the
  // socket with its front just proud of the socket floor.
  // Bisect for the z where (x, y, z) crosses the unrelieved surface.
  float inside = 0.0f, outside = 2.0f * kAxes.z;
  for (int i = 0; i < 30; ++i) {
    const float z = 0.5f * (inside + outside);
    const glm::vec3 p(x, kEye.y, z);
    (glm::length(p) < ellipsoid_radius(glm::normalize(p)) ? inside : outside) = z;
  }
  const float front_z = inside - 0.009f;
  return glm::vec3(x, kEye.y, front_z - kEyeRadius);
}

float eye_radius() {
  return kEyeRadius;
}
float neck_bottom_y() {
  return kNeckBottomY;
}
float neck_center_z() {
  return kNeckCenterZ;
}

Regions regions_at(const glm::vec3& p) {
  Regions r;
  const float front = smoothstep(0.02f, 0.06f, p.z);
  const glm::vec2 q(p.x, p.y);
  const glm::vec2 m(std::abs(p.x), p.y);
  // Lips: an ellipse around the mouth, sharper at the top edge (vermilion border).
  r.lips =
      front * smoothstep(1.0f, 0.6f,
                         glm::length((q - glm::vec2(0.0f, -0.0685f)) / glm::vec2(0.024f, 0.0115f)));
  // Brows: arcs above the eyes, thinning outwards.
  const float brow_y = 0.034f + 0.004f * (1.0f - std::pow((m.x - 0.032f) / 0.02f, 2.0f));
  r.brows = front * smoothstep(0.6f, 0.0f, std::abs(m.y - brow_y) / 0.0055f) *
            smoothstep(0.058f, 0.045f, m.x) * smoothstep(0.008f, 0.014f, m.x);
  r.t_zone = front * std::max({bump(q, {0.0f, 0.065f}, {0.045f, 0.03f}),
                               bump(q, {0.0f, -0.02f}, {0.014f, 0.04f}),
                               bump(q, {0.0f, -0.1f}, {0.02f, 0.015f})});
  r.cheeks = front * bump(m, {0.045f, -0.03f}, {0.02f, 0.018f});
  r.eye_lids = front * bump(m, kEye, {0.02f, 0.014f});
  r.forehead = front * smoothstep(0.045f, 0.055f, p.y) * smoothstep(0.1f, 0.085f, p.y) *
               smoothstep(0.055f, 0.03f, m.x);
  r.crow_feet = front * bump(m, {0.056f, 0.01f}, {0.007f, 0.012f});
  r.nasolabial = front * bump(m, {0.026f, -0.052f}, {0.006f, 0.016f});
  return r;
}

}  // namespace skinsim::scene::head
