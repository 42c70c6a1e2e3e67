// The ground-truth frame image quality is measured against: same scene, camera and
// lights as the pipelines, computed without their approximations.
//
//   - irradiance at full resolution, per pixel, in float, from the normal-mapped normal, of
//     the key and back lights (lighting.h) with exact visibility: shadow rays cast with
//     Embree against every mesh towards a disc light 1 degree in radius (soft edges), and
//     light transmitted through thin parts from the baked thickness and the profile's
//     transmittance (as shaders/lights.h), whatever the shadows / transmission knobs; the
//     ambient and the environment's reflection dimmed by what of them the character hides
//     (ambient_visibility.h);
//   - subsurface diffusion with the six-Gaussian skin profile (d'Eon & Luebke), or with
//     Jensen et al.'s dipole (reference_profile, dipole_diffusion.h), as a 2D convolution
//     whose kernel is evaluated on the world-space distance between surface points (so it
//     does not bleed across depth discontinuities), normalised over skin;
//   - dual-lobe Kelemen/Szirmay-Kalos specular (Beckmann, Schlick Fresnel with the half
//     vector, 1/|L+V|^2 geometry) evaluated analytically per pixel;
//   - the diffuse energy-conservation term evaluated analytically per pixel (no LUT);
//   - exact sRGB decoding of albedo and encoding of the result, all maths in float.
// What it still approximates is documented in docs/reference.md.
#pragma once

#include "pipeline/config.h"
#include "pipeline/gpu_scene.h"
#include "sim/render_target.h"

namespace skinsim::pipeline {

struct ReferenceFrame {
  sim::RenderTarget frame;              // display-encoded RGBA32F, alpha 1
  std::vector<std::uint8_t> skin_mask;  // 1 where skin is the visible surface
};

// Renders the reference at config.width x config.height with `threads` host threads
// (results identical for any count).
ReferenceFrame render_reference(const GpuScene& scene, const PipelineConfig& config, int threads);

}  // namespace skinsim::pipeline
