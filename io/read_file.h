// Reading input files a user names (device profiles, budgets, baselines, sweep files, results)
// without trusting them: only regular files, only up to a stated size, never blocking on a
// FIFO or reading /dev/zero forever.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "util/user_error.h"

namespace skinsim::io {

// A file the user named cannot be read: missing, not a regular file, too large, unreadable.
class InputError : public UserError {
 public:
  using UserError::UserError;
};

// Text inputs (TOML, JSON, CSV) are kilobytes; 64 MiB leaves room for a large sweep's
// results.json while refusing runaway files long before memory is at risk.
inline constexpr std::uintmax_t kMaxTextFileBytes = std::uintmax_t{64} << 20;

// Throws InputError "<what> <path>: <reason>" unless `path` names a regular file (symlinks
// followed) of at most `max_bytes`.
void require_regular_file(const std::filesystem::path& path, std::string_view what,
                          std::uintmax_t max_bytes = kMaxTextFileBytes);

// The whole content of a regular file of at most `max_bytes`; throws InputError as above.
// Opens without blocking (a FIFO is refused, not waited on) and checks the opened file, so
// the file read is the file checked.
std::string read_regular_file(const std::filesystem::path& path, std::string_view what,
                              std::uintmax_t max_bytes = kMaxTextFileBytes);

// read_regular_file of `path` itself: a symlink there is refused (O_NOFOLLOW), not followed.
// For files in a shared directory that skinsim owns (the reference store).
std::string read_own_file(const std::filesystem::path& path, std::string_view what,
                          std::uintmax_t max_bytes = kMaxTextFileBytes);

// "12.0 MiB", "512 bytes": sizes in messages.
std::string format_bytes(std::uintmax_t bytes);

}  // namespace skinsim::io
