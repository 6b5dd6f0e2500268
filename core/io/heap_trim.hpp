#pragma once
// glibc gives the free memory at the top of the heap back to the system once it exceeds the trim
// threshold (128 KB by default). A frame that frees a large block there and allocates it again
// (llvmpipe's draw module does, per draw, for its vertex data) then faults and zeroes those pages
// again inside the timed passes: on orchard:1000 the opaque pass took 354 ms instead of 169, and
// whether it happened turned on where other allocations happened to lie. keepFreedHeap() raises
// the threshold, so the process keeps up to that much free heap for reuse, and keeps large
// blocks on the heap rather than mapping each anew. Call it once, first.
namespace strata {

void keepFreedHeap();

}  // namespace strata
