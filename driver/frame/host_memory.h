// Host allocator tuning for the emulator's allocation pattern.
#pragma once

namespace skinsim::driver {

// Every frame allocates and frees render targets and texture copies of 10-50 MB each. By
// default glibc serves such blocks with mmap and returns them with munmap, so the next
// frame faults every page in again (~30k page faults per 2048x1536 frame), and page faults
// serialise the emulator's host threads on the kernel's memory map. Serving them from the
// heap and keeping freed memory there makes later frames reuse already-mapped pages. Peak
// memory is unchanged. Call once at process start; a no-op on non-glibc systems.
void retain_freed_memory();

}  // namespace skinsim::driver
