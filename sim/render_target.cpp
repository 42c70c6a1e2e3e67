#include "sim/render_target.h"

namespace skinsim::sim {

Texture2D as_texture(const RenderTarget& target, SamplerState sampler) {
  // Tiles resolve quantised values (TileRenderer), so the pixels are already as stored.
  return Texture2D::from_stored(target.name, target.width, target.height, target.pixels,
                                target.format, sampler);
}

}  // namespace skinsim::sim
