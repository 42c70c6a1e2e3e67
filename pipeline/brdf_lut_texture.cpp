#include "pipeline/brdf_lut_texture.h"

#include <algorithm>
#include <mutex>
#include <vector>

namespace skinsim::pipeline {

bake::BrdfLutParams brdf_lut_params(const PipelineConfig& c) {
  bake::BrdfLutParams p;
  p.width = c.lut_width;
  p.height = c.lut_height;
  p.m1 = c.lobe1.roughness;
  p.m2 = c.lobe2.roughness;
  p.weight1 = c.lobe1.weight;
  p.weight2 = c.lobe2.weight;
  p.rho_s = c.specular_intensity;
  return p;
}

BrdfLutTexture BrdfLutTexture::bake(const PipelineConfig& config) {
  const bake::LutFormat format = config.lut_format == sim::TexelFormat::kRGBA16F
                                     ? bake::LutFormat::kRGBA16F
                                     : bake::LutFormat::kRGBA8;
  bake::BrdfLut stored = bake::quantize(bake::bake_brdf_lut(brdf_lut_params(config)), format);
  std::vector<sim::MipLevel> levels;
  for (const bake::LutLevel& level : stored.levels) {
    levels.push_back({level.width, level.height, level.texels});
  }
  sim::Texture2D texture("brdf_lut", std::move(levels), config.lut_format,
                         {sim::Filter::kTrilinear, sim::Wrap::kClamp});
  return BrdfLutTexture(std::move(stored), std::move(texture));
}

std::shared_ptr<const BrdfLutTexture> BrdfLutTexture::shared(const PipelineConfig& config) {
  struct Entry {
    bake::BrdfLutParams params;
    sim::TexelFormat format;
    std::shared_ptr<const BrdfLutTexture> lut;
  };
  // A sweep visits a handful of LUT sizes; keeping the most recent few bounds memory (a
  // 128x512 LUT with its mips is ~1.4 MB of floats, held twice: the baked levels and the
  // texture).
  constexpr std::size_t kKept = 8;
  static std::mutex mutex;
  static std::vector<Entry> entries;  // most recently used last

  const bake::BrdfLutParams params = brdf_lut_params(config);
  const std::lock_guard<std::mutex> lock(mutex);
  for (auto it = entries.begin(); it != entries.end(); ++it) {
    if (it->params == params && it->format == config.lut_format) {
      std::rotate(it, it + 1, entries.end());
      return entries.back().lut;
    }
  }
  // Baking under the lock: concurrent callers with the same config wait for one bake
  // instead of each running their own.
  auto lut = std::make_shared<const BrdfLutTexture>(bake(config));
  if (entries.size() == kKept) entries.erase(entries.begin());
  entries.push_back({params, config.lut_format, lut});
  return lut;
}

}  // namespace skinsim::pipeline
