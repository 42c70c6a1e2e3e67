#include "io/read_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace skinsim::io {

namespace {

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

[[noreturn]] void fail(std::string_view what, const std::filesystem::path& path,
                       const std::string& why) {
  throw InputError(fmt::format("{} {}: {}", what, path.string(), why));
}

void check_stat(const struct stat& st, const std::filesystem::path& path, std::string_view what,
                std::uintmax_t max_bytes) {
  if (!S_ISREG(st.st_mode)) fail(what, path, "is " + kind_of(st.st_mode) + ", not a regular file");
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) {
    fail(what, path,
         fmt::format("is {}, larger than the {} this input may be",
                     format_bytes(static_cast<std::uintmax_t>(st.st_size)),
                     format_bytes(max_bytes)));
  }
}

// Closes the descriptor on every path out of read_regular_file.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string format_bytes(std::uintmax_t bytes) {
  if (bytes < 1024) return fmt::format("{} bytes", bytes);
  if (bytes < (std::uintmax_t{1} << 20)) return fmt::format("{:.1f} KiB", bytes / 1024.0);
  if (bytes < (std::uintmax_t{1} << 30)) return fmt::format("{:.1f} MiB", bytes / 1048576.0);
  return fmt::format("{:.1f} GiB", bytes / 1073741824.0);
}

void require_regular_file(const std::filesystem::path& path, std::string_view what,
                          std::uintmax_t max_bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) fail(what, path, std::strerror(errno));
  check_stat(st, path, what, max_bytes);
}

namespace {

std::string read_opened(const std::filesystem::path& path, std::string_view what,
                        std::uintmax_t max_bytes, int extra_flags) {
  // O_NONBLOCK: opening a FIFO with no writer would otherwise wait forever.
  const Fd file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | extra_flags)};
  if (file.fd < 0) {
    // O_NOFOLLOW on a symlink fails with ELOOP, whose text ("too many levels") misleads.
    fail(what, path,
         (extra_flags & O_NOFOLLOW) && errno == ELOOP ? "is a symlink" : std::strerror(errno));
  }
  struct stat st {};
  if (::fstat(file.fd, &st) != 0) fail(what, path, std::strerror(errno));
  check_stat(st, path, what, max_bytes);

  std::string content(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t filled = 0;
  for (;;) {
    if (filled == content.size()) {
      // The file may have grown since fstat: read on, within the limit.
      if (content.size() >= max_bytes) {
        char probe;
        const ssize_t n = ::read(file.fd, &probe, 1);
        if (n == 0) break;
        fail(what, path,
             fmt::format("grew past the {} this input may be", format_bytes(max_bytes)));
      }
      content.resize(std::min<std::uintmax_t>(max_bytes, content.size() * 2 + 4096));
    }
    const ssize_t n = ::read(file.fd, content.data() + filled, content.size() - filled);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(what, path, std::string("read failed: ") + std::strerror(errno));
    }
    if (n == 0) break;
    filled += static_cast<std::size_t>(n);
  }
  content.resize(filled);
  return content;
}

}  // namespace

std::string read_regular_file(const std::filesystem::path& path, std::string_view what,
                              std::uintmax_t max_bytes) {
  return read_opened(path, what, max_bytes, 0);
}

std::string read_own_file(const std::filesystem::path& path, std::string_view what,
                          std::uintmax_t max_bytes) {
  return read_opened(path, what, max_bytes, O_NOFOLLOW);
}

}  // namespace skinsim::io
