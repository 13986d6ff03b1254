#include "engine/render/hemicube.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace mvpl::render {

namespace {

// The face's major axis M and the axes S, T of its (s_c, t_c) (shadow.vert): the direction
// through NDC (x, y) is M + x S + y T, framebuffer column ↔ x and row ↔ y.
struct FaceAxes {
    Vec3 m, s, t;
};

FaceAxes face_axes(uint32_t face) {
    switch (face) {
        case 0:
            return {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}};
        case 1:
            return {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}};
        case 2:
            return {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
        case 3:
            return {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}};
        case 4:
            return {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}};
        default:
            return {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}};
    }
}

}  // namespace

std::optional<FaceRect> lit_face_rect(const Vec3& n, uint32_t face, uint32_t res) {
    // n·ω = a + b x + c y over the square [−1, 1]², linear: the lit part (≥ −ε) is the square
    // clipped by a half-plane, whose bounding box comes from the lit corners and the points
    // where the edges cross the line.
    constexpr float kEpsilon = 1e-3f;  // as the whole-face test it replaces
    const FaceAxes f = face_axes(face);
    const float a = glm::dot(n, f.m) + kEpsilon;
    const float b = glm::dot(n, f.s);
    const float c = glm::dot(n, f.t);
    const std::array<Vec2, 4> corners = {Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)};
    Vec2 lo(2.0f), hi(-2.0f);
    const auto add = [&](const Vec2& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    };
    for (size_t i = 0; i < 4; ++i) {
        const Vec2 p = corners[i];
        const Vec2 q = corners[(i + 1) % 4];
        const float fp = a + b * p.x + c * p.y;
        const float fq = a + b * q.x + c * q.y;
        if (fp >= 0.0f) add(p);
        if ((fp < 0.0f) != (fq < 0.0f)) add(p + (q - p) * (fp / (fp - fq)));
    }
    if (hi.x < lo.x) return std::nullopt;
    const auto first = [&](float v) {
        const float t = std::floor((v + 1.0f) * 0.5f * float(res)) - float(kHemicubeMargin);
        return uint32_t(std::clamp(t, 0.0f, float(res - 1)));
    };
    const auto last = [&](float v) {
        const float t = std::floor((v + 1.0f) * 0.5f * float(res)) + float(kHemicubeMargin);
        return uint32_t(std::clamp(t, 0.0f, float(res - 1)));
    };
    const uint32_t x0 = first(lo.x), x1 = last(hi.x), y0 = first(lo.y), y1 = last(hi.y);
    return FaceRect{x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

}  // namespace mvpl::render
