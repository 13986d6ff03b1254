#include "engine/reference/progressive_trace.h"

#include <algorithm>

#include "engine/core/progress.h"
#include "engine/core/timer.h"

namespace mvpl::reference {

int next_spp_chunk(int done, double elapsed, int remaining) {
    if (remaining <= 0) return 0;
    if (done <= 0 || !(elapsed > 0.0)) return 1;
    const double per_spp = elapsed / double(done);
    const double fit = std::min(kChunkSeconds / per_spp, double(remaining));
    return std::max(1, int(fit));
}

void trace_progressively(const PathTracer& tracer, PathFilm& film, const PathTracerOptions& options,
                         RenderStats* stats, const CameraSampleHook& on_sample,
                         const ChunkGate& go_on) {
    Progress progress("reference", int64_t(options.height) * options.spp, options.quiet);
    Timer clock;
    const int start = film.spp();
    while (film.spp() < options.spp && (!go_on || go_on(film))) {
        const int chunk =
            next_spp_chunk(film.spp() - start, clock.seconds(), options.spp - film.spp());
        tracer.advance(film, chunk, options, stats, on_sample, &progress);
    }
    progress.finish();
}

}  // namespace mvpl::reference
