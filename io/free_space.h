// Room for an output before it is written: a command that knows how much it is about to
// write (an export's data, hundreds of megabytes at large resolutions) says so up front
// instead of failing half way through with a full disk.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace skinsim::io {

// Throws UserError naming `what`, `dir` and both sizes when the filesystem holding `dir`
// (which must exist) has less than `bytes` available to this user.
void require_free_space(const std::filesystem::path& dir, std::uintmax_t bytes,
                        const std::string& what);

// "467.2 MB": bytes in decimal megabytes, as the CLI prints sizes.
std::string megabytes(std::uintmax_t bytes);

}  // namespace skinsim::io
