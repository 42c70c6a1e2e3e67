// An exclusive advisory lock on a file, held for a scope: how processes that share an output
// directory (sweep shards on one machine or on a cluster's shared file system) agree that only
// one of them builds a shared output. flock(2): the kernel releases the lock when its holder
// exits or is killed, so a crashed holder never leaves the others waiting; on NFS, Linux maps
// flock to byte-range locks that the server arbitrates (nfs(5), "flock").
#pragma once

#include <filesystem>
#include <functional>

namespace skinsim::io {

class FileLock {
 public:
  // Creates `path` if needed and blocks until this process holds the lock. When another
  // process holds it, `on_wait` (if set) is called once before waiting, e.g. to say so.
  // Throws OutputError naming the path when it cannot be created or locked.
  explicit FileLock(const std::filesystem::path& path, const std::function<void()>& on_wait = {});
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace skinsim::io
