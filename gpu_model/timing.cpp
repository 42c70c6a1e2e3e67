#include "gpu_model/timing.h"

namespace skinsim::gpu_model {

const char* unit_name(Unit u) {
  switch (u) {
    case Unit::kAlu:
      return "alu";
    case Unit::kTexture:
      return "texture";
    case Unit::kIsp:
      return "isp";
    case Unit::kBandwidth:
      return "bandwidth";
    case Unit::kTiler:
      return "tiler";
    case Unit::kOverhead:
      return "overhead";
  }
  return "overhead";
}

void DramBytes::add(const DramBytes& o) {
  parameter_write += o.parameter_write;
  parameter_read += o.parameter_read;
  texture += o.texture;
  color_load += o.color_load;
  color_store += o.color_store;
  depth_load += o.depth_load;
  depth_store += o.depth_store;
}

}  // namespace skinsim::gpu_model
