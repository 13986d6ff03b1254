#include "engine/aov/aov_film.h"

#include <utility>

namespace mvpl::aov {

AovFilm::AovFilm(std::vector<AovRequest> requests, int width, int height)
    : m_requests(std::move(requests)), m_width(width), m_height(height) {
    for (const AovRequest& r : m_requests)
        m_sums.emplace_back(size_t(width) * size_t(height) * size_t(components(r.kind)), 0.0f);
}

void AovFilm::add(int x, int y, const AovSample& s) {
    const size_t pixel = size_t(y) * size_t(m_width) + size_t(x);
    for (size_t i = 0; i < m_requests.size(); ++i) {
        float* v = m_sums[i].data() + pixel * size_t(components(m_requests[i].kind));
        switch (m_requests[i].kind) {
            case Aov::Albedo:
                for (int c = 0; c < 3; ++c)
                    v[c] += s.albedo[c];
                break;
            case Aov::Normal:
                for (int c = 0; c < 3; ++c)
                    v[c] += s.normal[c];
                break;
            case Aov::Position:
                for (int c = 0; c < 3; ++c)
                    v[c] += s.position[c];
                break;
            case Aov::Depth:
                v[0] += s.depth;
                break;
        }
    }
}

std::vector<ChannelImage> AovFilm::images(uint64_t samples) const {
    std::vector<ChannelImage> out;
    const float scale = samples > 0 ? float(1.0 / double(samples)) : 0.0f;
    for (size_t i = 0; i < m_requests.size(); ++i) {
        ChannelImage image{m_requests[i].name, m_requests[i].channels, m_width, m_height,
                           m_sums[i]};
        for (float& v : image.values)
            v *= scale;
        out.push_back(std::move(image));
    }
    return out;
}

}  // namespace mvpl::aov
