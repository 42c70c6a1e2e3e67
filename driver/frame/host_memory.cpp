#include "driver/frame/host_memory.h"

#include <cstdlib>  // defines __GLIBC__ on glibc systems

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace skinsim::driver {

void retain_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_MAX, 0);              // no block is served by a private mmap
  mallopt(M_TRIM_THRESHOLD, 1 << 30);  // keep up to 1 GiB of free memory at the heap top
#endif
}

}  // namespace skinsim::driver
