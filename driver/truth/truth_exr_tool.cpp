// skinsim-exr: converts between any image OpenImageIO reads (OpenEXR above all) and the raw
// float file of driver/truth/truth_image.h, so that skinsim itself never loads OpenImageIO.
//   skinsim-exr to-raw IMAGE RAW     RGB of IMAGE (grey replicated; alpha dropped) as stored
//   skinsim-exr from-raw RAW EXR     a float RGB OpenEXR
// Exit 0 done, 2 bad input (the message names the file).
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cstdio>
#include <exception>
#include <string>

#include "driver/truth/truth_image.h"

namespace {

namespace oiio = OIIO;
using skinsim::driver::LinearImage;

int to_raw(const std::string& from, const std::string& to) {
  oiio::ImageBuf in(from);
  if (!in.read(0, 0, true, oiio::TypeDesc::FLOAT)) {
    std::fprintf(stderr, "skinsim-exr: %s: %s\n", from.c_str(), in.geterror().c_str());
    return 2;
  }
  const oiio::ImageSpec& spec = in.spec();
  const int channels = spec.nchannels;
  const int c1 = channels >= 3 ? 1 : 0, c2 = channels >= 3 ? 2 : 0;  // grey: replicated
  LinearImage image{spec.width, spec.height, {}};
  image.rgb.resize(static_cast<std::size_t>(spec.width) * spec.height);
  for (oiio::ImageBuf::ConstIterator<float> p(in); !p.done(); ++p) {
    image.rgb[static_cast<std::size_t>(p.y() - spec.y) * spec.width + (p.x() - spec.x)] = {
        p[0], p[c1], p[c2]};
  }
  skinsim::driver::write_raw_image(image, to);
  return 0;
}

int from_raw(const std::string& from, const std::string& to) {
  const LinearImage image = skinsim::driver::read_raw_image(from);
  oiio::ImageSpec spec(image.width, image.height, 3, oiio::TypeDesc::FLOAT);
  spec.channelnames = {"R", "G", "B"};
  oiio::ImageBuf out(spec, const_cast<glm::vec3*>(image.rgb.data()));
  if (!out.write(to)) {
    std::fprintf(stderr, "skinsim-exr: %s: %s\n", to.c_str(), out.geterror().c_str());
    return 2;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc == 4 ? argv[1] : "";
  try {
    if (mode == "to-raw") return to_raw(argv[2], argv[3]);
    if (mode == "from-raw") return from_raw(argv[2], argv[3]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "skinsim-exr: %s\n", e.what());
    return 2;
  }
  std::fprintf(stderr, "usage: skinsim-exr to-raw IMAGE RAW | from-raw RAW EXR\n");
  return 2;
}
