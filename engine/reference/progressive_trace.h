#pragma once
// A reference traced in chunks of whole samples per pixel, so that its caller can act between
// them: end on Ctrl-C with the image so far (`mvpl reference`, mvpl.reference), rewrite its
// outputs (--write-every), report progress. The chunks change nothing in the image
// (path_film.h): they are sized by the clock.
#include <functional>

#include "engine/reference/path_film.h"
#include "engine/reference/path_tracer.h"

namespace mvpl::reference {

// Seconds of tracing aimed at per chunk: short enough that a signal ends a reference soon (the
// chunk in flight is finished), long enough that a chunk's parallel loop over rows costs little
// beside its samples.
constexpr double kChunkSeconds = 0.5;

// Samples per pixel for the next chunk: one while nothing is measured, then about
// kChunkSeconds at the rate measured so far (`done` samples in `elapsed` seconds), never more
// than `remaining`, at least one.
int next_spp_chunk(int done, double elapsed, int remaining);

// Called before each chunk with the film as it is (film.spp() samples so far): true to go on.
using ChunkGate = std::function<bool(const PathFilm& film)>;

// Advances `film` to options.spp samples per pixel, chunk by chunk, or until `go_on` says no;
// `stats` sums the chunks; a progress bar (or plain lines) over the whole unless options.quiet.
void trace_progressively(const PathTracer& tracer, PathFilm& film, const PathTracerOptions& options,
                         RenderStats* stats, const CameraSampleHook& on_sample,
                         const ChunkGate& go_on);

}  // namespace mvpl::reference
