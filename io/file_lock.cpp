#include "io/file_lock.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "io/atomic_file.h"

namespace skinsim::io {

namespace {

int lock_retrying(int fd, int operation) {
  int result = 0;
  do {
    result = ::flock(fd, operation);
  } while (result != 0 && errno == EINTR);
  return result;
}

}  // namespace

FileLock::FileLock(const std::filesystem::path& path, const std::function<void()>& on_wait) {
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw OutputError(
        fmt::format("cannot create lock file {}: {}", path.string(), std::strerror(errno)));
  }
  if (lock_retrying(fd_, LOCK_EX | LOCK_NB) == 0) return;
  const int busy = errno;
  if (busy == EWOULDBLOCK) {
    if (on_wait) on_wait();
    if (lock_retrying(fd_, LOCK_EX) == 0) return;
  }
  const int error = busy == EWOULDBLOCK ? errno : busy;
  ::close(fd_);
  throw OutputError(fmt::format("cannot lock {}: {}", path.string(), std::strerror(error)));
}

FileLock::~FileLock() {
  ::close(fd_);  // releases the lock
}

}  // namespace skinsim::io
