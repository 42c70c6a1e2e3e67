// The texture-space technique's own knob (texture_space.cpp binds it), nested in
// PipelineConfig as `texture_space`.
#pragma once

namespace skinsim::pipeline {

struct TextureSpaceParams {
  int size = 1024;  // texture-space diffusion buffers, texels per axis
};

}  // namespace skinsim::pipeline
