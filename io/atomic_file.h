// Writing output files so a reader never sees half of one: the bytes go to a temporary file
// beside the target, every write and the close are checked, and only a complete file is
// renamed over the target (rename is atomic within one file system, POSIX).
#pragma once

#include <filesystem>
#include <string_view>

#include "util/user_error.h"

namespace skinsim::io {

// An output cannot be written: no space, no permission, a directory in the way.
class OutputError : public UserError {
 public:
  using UserError::UserError;
};

// Writes `content` to `path`, throwing OutputError "cannot write <path>: <reason>".
// - A symlink is followed to its final target, which is replaced (the link stays a link).
// - A regular or missing target is replaced atomically: on failure the old file is untouched
//   and no temporary is left behind.
// - A character device or FIFO (e.g. /dev/stdout, /dev/null, a pipe) is written directly, as
//   it cannot be replaced; a FIFO without a reader is an error, not a hang.
// - A directory (or socket, block device) is refused.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace skinsim::io
