// The LUT texture as a PNG, apart from the texture so that code which only renders links no
// image library.
#include "pipeline/brdf_lut_texture.h"

namespace skinsim::pipeline {

void BrdfLutTexture::write_png(const std::string& path) const {
  bake::write_lut_png(stored_, path);
}

}  // namespace skinsim::pipeline
