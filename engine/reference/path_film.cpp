#include "engine/reference/path_film.h"

#include "engine/core/parallel.h"

namespace mvpl::reference {

PathFilm::PathFilm(int width, int height, uint64_t seed)
    : m_width(width),
      m_height(height),
      m_rngs(size_t(width) * size_t(height)),
      m_sums(size_t(width) * size_t(height), DVec3(0.0)) {
    const uint64_t mixed = mix_bits(seed);
    parallel_for(int64_t(m_rngs.size()), 4096, [&](int64_t begin, int64_t end) {
        for (int64_t pixel = begin; pixel < end; ++pixel)
            m_rngs[size_t(pixel)].seed(mixed, uint64_t(pixel));
    });
}

Image PathFilm::image() const {
    Image out(m_width, m_height);
    if (m_spp == 0) return out;
    // As one call divides: the sum in double by the count, then rounded to float.
    for (size_t i = 0; i < m_sums.size(); ++i)
        out.pixels()[i] = Rgb(m_sums[i] / double(m_spp));
    return out;
}

}  // namespace mvpl::reference
