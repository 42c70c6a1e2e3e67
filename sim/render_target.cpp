#include "sim/render_target.h"

namespace skinsim::sim {

Texture2D texture_view(const RenderTarget& target, SamplerState sampler) {
  // Tiles resolve quantised values (TileRenderer), so the pixels are already as stored.
  return Texture2D::view_of_stored(target.name, target.width, target.height, target.pixels.data(),
                                   target.format, sampler);
}

}  // namespace skinsim::sim
