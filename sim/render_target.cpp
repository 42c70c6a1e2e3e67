#include "sim/render_target.h"

namespace skinsim::sim {

Texture2D as_texture(const RenderTarget& target, SamplerState sampler) {
  return Texture2D(target.name, target.width, target.height, target.pixels, target.format,
                   sampler, false);
}

}  // namespace skinsim::sim
