#pragma once
// The AOVs of an image, summed sample by sample per pixel and averaged: each pixel's AOV is the
// mean over the same sub-pixel positions as its colour, so that an edge pixel holds the coverage
// mix as the image does (aov_images.h).
#include <cstdint>
#include <vector>

#include "engine/aov/aov_kind.h"
#include "engine/aov/aov_tracer.h"
#include "engine/core/exr_file.h"

namespace mvpl::aov {

class AovFilm {
public:
    AovFilm(std::vector<AovRequest> requests, int width, int height);

    // Adds one ray's values to pixel (x, y). Threads may add to different pixels at once.
    void add(int x, int y, const AovSample& sample);
    // Each AOV's sums divided by `samples` (the samples every pixel received), one image each in
    // the order requested, named and with channels as requested.
    std::vector<ChannelImage> images(uint64_t samples) const;

    const std::vector<AovRequest>& requests() const { return m_requests; }

private:
    std::vector<AovRequest> m_requests;
    int m_width;
    int m_height;
    std::vector<std::vector<float>> m_sums;  // per request, interleaved as ChannelImage
};

}  // namespace mvpl::aov
