#include "io/atomic_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "io/temp_files.h"

namespace skinsim::io {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& path, const std::string& why) {
  throw OutputError(fmt::format("cannot write {}: {}", path.string(), why));
}

// The file a chain of symlinks ends at (which need not exist yet).
fs::path final_target(const fs::path& path) {
  fs::path current = path;
  for (int hops = 0; hops < 40; ++hops) {  // 40: the kernel's own limit (ELOOP)
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(current, ec))) return current;
    const fs::path link = fs::read_symlink(current, ec);
    if (ec) fail(path, "cannot read symlink " + current.string() + ": " + ec.message());
    current = link.is_absolute() ? link : current.parent_path() / link;
  }
  fail(path, "too many levels of symbolic links");
}

// Writes all of `content` to `fd` and closes it; returns the errno of the first failure, or 0.
int write_all_and_close(int fd, std::string_view content) {
  int error = 0;
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error = n < 0 ? errno : EIO;
      break;
    }
    done += static_cast<std::size_t>(n);
  }
  // close() reports delayed write errors (NFS, quota): a file is complete only if it succeeds.
  if (::close(fd) != 0 && error == 0) error = errno;
  return error;
}

// A device or FIFO cannot be replaced, only written to.
void write_in_place(const fs::path& path, const fs::path& target, bool is_fifo,
                    std::string_view content) {
  // O_NONBLOCK: opening a FIFO nobody reads fails (ENXIO) instead of waiting forever.
  const int fd = ::open(target.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    if (is_fifo && errno == ENXIO) fail(path, "is a FIFO that nobody is reading");
    fail(path, std::strerror(errno));
  }
  // Blocking writes from here on: a reader that is slower than us is not an error.
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  if (const int error = write_all_and_close(fd, content)) fail(path, std::strerror(error));
}

void replace_atomically(const fs::path& path, const fs::path& target, std::string_view content) {
  const fs::path temp = temporary_path_beside(target);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) fail(path, fmt::format("cannot create {}: {}", temp.string(), std::strerror(errno)));
  int error = write_all_and_close(fd, content);
  if (error == 0 && ::rename(temp.c_str(), target.c_str()) != 0) error = errno;
  if (error != 0) {
    ::unlink(temp.c_str());  // after saving errno: the message names the first failure
    fail(path, std::strerror(error));
  }
}

}  // namespace

void write_file_atomically(const fs::path& path, std::string_view content) {
  const fs::path target = final_target(path);
  struct stat st {};
  if (::stat(target.c_str(), &st) != 0) {
    if (errno != ENOENT) fail(path, std::strerror(errno));
    replace_atomically(path, target, content);
  } else if (S_ISREG(st.st_mode)) {
    replace_atomically(path, target, content);
  } else if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
    write_in_place(path, target, S_ISFIFO(st.st_mode), content);
  } else if (S_ISDIR(st.st_mode)) {
    fail(path, "is a directory");
  } else {
    fail(path, "is not a regular file, character device or FIFO");
  }
}

void require_not_input(const fs::path& output, std::string_view option, const fs::path& input,
                       std::string_view what) {
  std::error_code ec;
  // fs::equivalent compares device and inode of the files the paths resolve to.
  if (!input.empty() && fs::equivalent(output, input, ec) && !ec) {
    throw OutputError(fmt::format(
        "{} {}: is also {} ({}); an output may not replace an input: choose another file", option,
        output.string(), what, input.string()));
  }
}

void replace_file_entry(const fs::path& path, std::string_view content) {
  replace_atomically(path, path, content);
}

}  // namespace skinsim::io
