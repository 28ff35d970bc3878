#include "util/prefault.h"

#include <cstdint>
#include <sys/mman.h>
#include <unistd.h>

namespace strata {

bool prefault(void* begin, size_t bytes) {
#ifdef MADV_POPULATE_WRITE
    const auto pageSize = static_cast<uintptr_t>(sysconf(_SC_PAGESIZE));
    // madvise takes whole pages; the partial pages at either end fault in as usual.
    const uintptr_t first = (reinterpret_cast<uintptr_t>(begin) + pageSize - 1) & ~(pageSize - 1);
    const uintptr_t end = (reinterpret_cast<uintptr_t>(begin) + bytes) & ~(pageSize - 1);
    if (end <= first) return false;
    return madvise(reinterpret_cast<void*>(first), end - first, MADV_POPULATE_WRITE) == 0;
#else
    (void)begin;
    (void)bytes;
    return false;
#endif
}

}  // namespace strata
