#include "engine/core/parallel.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

namespace mvpl {

void parallel_for(int64_t count, int64_t grain, const std::function<void(int64_t, int64_t)>& body) {
    if (count <= 0) return;
    tbb::parallel_for(tbb::blocked_range<int64_t>(0, count, grain > 0 ? grain : 1),
                      [&](const tbb::blocked_range<int64_t>& r) { body(r.begin(), r.end()); });
}

int worker_count() {
    return tbb::info::default_concurrency();
}

}  // namespace mvpl
