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

// Writes `content` through a temporary in `path`'s directory renamed over the directory entry
// `path`: whatever is there (a symlink included) is replaced, never followed or written
// through, so a link planted in a shared directory (the reference store) cannot redirect the
// write. Throws OutputError as above.
void replace_file_entry(const std::filesystem::path& path, std::string_view content);

// Throws OutputError "<option> <output>: is also <what> (<input>); ..." when `output` names the
// file `input` names: the same file once symlinks are resolved, or another hard link to it
// (the same device and inode). An input or output that does not exist is no clash. Checked
// before any work, so that a command never replaces its own input.
void require_not_input(const std::filesystem::path& output, std::string_view option,
                       const std::filesystem::path& input, std::string_view what);

}  // namespace skinsim::io
