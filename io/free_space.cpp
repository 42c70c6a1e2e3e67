#include "io/free_space.h"

#include <fmt/format.h>

#include "util/user_error.h"

namespace skinsim::io {

void require_free_space(const std::filesystem::path& dir, std::uintmax_t bytes,
                        const std::string& what) {
  const std::filesystem::space_info space = std::filesystem::space(dir);
  if (space.available >= bytes) return;
  throw UserError(fmt::format("{}: needs {} in '{}', but its filesystem has {} free", what,
                              megabytes(bytes), dir.string(), megabytes(space.available)));
}

std::string megabytes(std::uintmax_t bytes) {
  return fmt::format("{:.1f} MB", static_cast<double>(bytes) / 1e6);
}

}  // namespace skinsim::io
