#pragma once
// A path-traced image in progress: every pixel's random-number stream where its last sample left
// it and the sum of its samples so far, so that the path tracer can add samples per pixel in
// chunks (Ctrl-C between them, checkpoints: tools/cli/reference_command.cpp) and still give, for
// the same total, the image of one call to the bit: each pixel draws the same numbers and sums
// the same samples in the same order whatever the chunks.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/core/image.h"
#include "engine/core/math.h"
#include "engine/core/rng.h"

namespace mvpl::reference {

class PathFilm {
public:
    // Every pixel's stream seeded as the reference always seeds it: (mix_bits(seed), pixel).
    PathFilm(int width, int height, uint64_t seed);

    int width() const { return m_width; }
    int height() const { return m_height; }
    // Samples every pixel holds.
    int spp() const { return m_spp; }
    // The mean of the samples so far, box-filtered per pixel (black before the first).
    Image image() const;

    // For the tracer: pixel (row-major) state, and the count once every pixel got `spp` more.
    Rng& rng(size_t pixel) { return m_rngs[pixel]; }
    DVec3& sum(size_t pixel) { return m_sums[pixel]; }
    void add_spp(int spp) { m_spp += spp; }

    // Host bytes a film holds per pixel.
    static constexpr uint64_t kBytesPerPixel = sizeof(Rng) + sizeof(DVec3);

private:
    int m_width;
    int m_height;
    int m_spp = 0;
    std::vector<Rng> m_rngs;
    std::vector<DVec3> m_sums;
};

}  // namespace mvpl::reference
