#include "budget/device_fingerprint.h"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <sstream>

#include "budget/error.h"
#include "io/read_file.h"

namespace skinsim::budget {

std::string fingerprint(std::string_view bytes) {
  // FNV-1a, 64-bit (Fowler, Noll, Vo): offset basis and prime from the reference
  // (http://www.isthe.com/chongo/tech/comp/fnv/).
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ull;
  }
  return fmt::format("fnv1a64:{:016x}", hash);
}

std::string file_fingerprint(const std::string& path) {
  return fingerprint(io::read_regular_file(path, "device profile"));
}

std::string skinsim_version() {
  return SKINSIM_VERSION;
}

}  // namespace skinsim::budget
