#pragma once
// The host memory a run may use, and the one sentence that refuses options whose buffers cannot
// fit in it: every command that sizes its buffers from the options (render's images,
// reference's film) checks them here before allocating, so that an impossible --res is refused
// up front with the estimate (exit 2) instead of failing or swapping half-way.
#include <cstdint>
#include <string>

namespace mvpl {

// Physical memory of this machine (sysconf), lowered to the address-space and data limits
// (ulimit -v, ulimit -d) where they are set; 0 where none can be told.
uint64_t host_memory_bytes();

// "1.2 GB": bytes in decimal gigabytes, as the estimates are written.
std::string gigabytes(uint64_t bytes);

// Empty when `needed` bytes fit in `available` (0: unknown, so anything fits); else
// "WHAT needs about N GB of host memory; this machine has M GB".
std::string host_memory_shortfall(const std::string& what, uint64_t needed, uint64_t available);

}  // namespace mvpl
