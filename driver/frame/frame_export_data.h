// The binary payloads of `skinsim export --data`: what a replay of the frame on another GPU
// needs besides the shaders (vertex data, textures) and what it is compared with (each
// pass's targets as the emulator left them). Little-endian, rows in the emulator's order
// (row 0 is the image's top and the texture's v = 0); RGBA8 data as bytes ("rgba8"), depth as
// one float32 ("r32f"), other formats as four ("rgba32f").
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "sim/render_pass.h"

namespace skinsim::driver {

class ExportData {
 public:
  // Files are added to `files` (path relative to the export → contents).
  explicit ExportData(std::map<std::string, std::string>* files) : files_(files) {}

  // Each written once however many draws use it; the JSON says where each part lies.
  nlohmann::json geometry(const sim::Geometry& g);
  nlohmann::json texture(const sim::Texture2D& t);
  nlohmann::json cube(const sim::TextureCube& c);
  // A target's pixels now (a later pass may render into it again).
  nlohmann::json target(const sim::RenderTarget& t, const std::string& file_stem);

 private:
  std::map<std::string, std::string>* files_;
  // By what was written (positions and indices for geometry; the texture; the cube).
  std::map<std::pair<const void*, const void*>, nlohmann::json> written_;
};

}  // namespace skinsim::driver
