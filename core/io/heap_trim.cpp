#include "io/heap_trim.hpp"

#include <cstddef>  // defines __GLIBC__ where the C library is glibc
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace strata {

void keepFreedHeap() {
#if defined(__GLIBC__)
    // 64 MB: more than any per-draw block seen (a draw's vertex data), little beside a frame's
    // targets and fragment buffers. Setting it turns off glibc's dynamic mmap threshold, which
    // would leave every block of 128 KB or more mapped and unmapped per use: blocks up to 32 MB
    // come from the heap too.
    mallopt(M_TRIM_THRESHOLD, 64 << 20);
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
#endif
}

}  // namespace strata
