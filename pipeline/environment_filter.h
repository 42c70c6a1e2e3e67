// Offline convolution of an environment cube map with the clamped-cosine lobe, so a skin
// shader can read diffuse-like environment light with one fetch along the vertex normal.
#pragma once

#include "scene/scene.h"

namespace skinsim::pipeline {

// Irradiance / pi for each output texel direction (a Lambertian surface's outgoing radiance
// per unit albedo), computed by brute-force integration over a downsampled copy of `src`.
scene::CubeMap cosine_filter(const scene::CubeMap& src, int out_size);

}  // namespace skinsim::pipeline
