#include "engine/core/host_memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace mvpl {

uint64_t host_memory_bytes() {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page_size = sysconf(_SC_PAGE_SIZE);
    uint64_t bytes = pages > 0 && page_size > 0 ? uint64_t(pages) * uint64_t(page_size) : 0;
    for (const int resource : {RLIMIT_AS, RLIMIT_DATA}) {
        rlimit limit{};
        if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) continue;
        bytes = bytes == 0 ? uint64_t(limit.rlim_cur) : std::min(bytes, uint64_t(limit.rlim_cur));
    }
    return bytes;
}

std::string gigabytes(uint64_t bytes) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f GB", double(bytes) / 1e9);
    return buf;
}

std::string host_memory_shortfall(const std::string& what, uint64_t needed, uint64_t available) {
    if (available == 0 || needed <= available) return {};
    return what + " needs about " + gigabytes(needed) + " of host memory; this machine has " +
           gigabytes(available);
}

}  // namespace mvpl
