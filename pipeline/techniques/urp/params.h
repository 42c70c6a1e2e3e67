// The urp technique's own knobs (urp.cpp binds them), nested in PipelineConfig as `urp`: the
// URP skin shader article's screen-space AO passes and their taps, the tiling pore detail
// normals, the clear-coat layer. It also reads the pre-integrated diffusion LUT's size
// (techniques/preintegrated/params.h).
#pragma once

namespace skinsim::pipeline {

inline constexpr int kMaxSsaoTaps = 32;  // screen-space AO taps per pixel

struct UrpParams {
  bool ssao = true;
  int ssao_taps = 12;
  bool detail_normals = true;
  bool clear_coat = true;
};

}  // namespace skinsim::pipeline
