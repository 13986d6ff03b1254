#pragma once
// Parallel loops over index ranges (oneTBB behind the interface, so that headers stay light).
#include <cstdint>
#include <functional>

namespace mvpl {

// Calls body(begin, end) on disjoint chunks covering [0, count), in parallel. Work must not depend
// on which thread or chunk runs it if the result is to be deterministic.
void parallel_for(int64_t count, int64_t grain, const std::function<void(int64_t, int64_t)>& body);

// Number of worker threads the loops use.
int worker_count();

}  // namespace mvpl
