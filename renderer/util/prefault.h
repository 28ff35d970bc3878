#pragma once
// Large buffers that a render writes in full (the accumulation buffer, the image it hands on) have
// their pages backed by the kernel in one call rather than one page fault per 4 KiB page at first
// touch. A fault is a trap into the kernel; in a virtual machine it can cost 10 us or more (10-15 us
// on the bench's), so a 256x256 accumulation buffer's 1,216 pages took 13 ms, a twentieth of a
// small render (docs/performance.md). Asking the kernel to populate the range (Linux 5.14 and
// later, MADV_POPULATE_WRITE) takes its share in one call (0.5 us a page there); the first write
// to each page then still costs the virtual machine's host about 5 us, so populating and writing
// take 5-7 us a page, about half. Where the kernel cannot, the pages fault in as before.
#include <cstddef>
#include <vector>

namespace strata {

// Backs the whole pages inside [begin, begin + bytes) with writable memory now. Returns whether
// the kernel did; nothing changes either way but when the faults happen.
bool prefault(void* begin, size_t bytes);

// v.resize(n) for an empty vector, its storage prefaulted before the elements are written.
template <class T>
void resizePrefaulted(std::vector<T>& v, size_t n) {
    v.reserve(n);
    prefault(v.data(), n * sizeof(T));
    v.resize(n);
}

}  // namespace strata
