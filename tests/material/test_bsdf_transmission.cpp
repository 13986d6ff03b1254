// KHR_materials_transmission in Bsdf (material/bsdf.h, transmission.h): sample/pdf/eval
// consistency in both hemispheres, energy at most 1, reciprocity (Walter et al. 2007's
// η-weighted form for refraction, plain for thin sheets), the adjoint, total internal
// reflection, and the smooth limits (a thin sheet passes light straight through with 1 − F0, a
// solid bends it by Snell's law).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/rng.h"
#include "engine/material/bsdf.h"
#include "engine/material/fresnel.h"
#include "tests/material/bsdf_cases.h"

namespace mvpl::material {
namespace {

using test::spherical_direction;

// A smooth (α = 10⁻⁴) lobe's directions: within kSnellTolerance of the ideal one for facets
// tilted by < 5 · 10⁻⁴ rad, a share 1 − α² / (α² + 2.5 · 10⁻⁷) = 0.96 of the samples (bounded
// below by kWithinTolerance); every one within kTailTolerance (facets < 0.05 rad: probability
// 4 · 10⁻⁶ a sample of exceeding it). SmoothLimits explains.
constexpr float kSnellTolerance = 2e-3f;
constexpr float kTailTolerance = 0.15f;
constexpr float kWithinTolerance = 0.9f;

ClosureParams glass(float roughness, bool thin, float t = 1.0f, const Rgb& tint = Rgb(1.0f)) {
    ClosureParams p;
    p.base_color = (1.0f - t) * tint;  // what graph_from_gltf's closure node holds
    p.metallic = 0.0f;
    p.roughness = roughness;
    p.ior = 1.5f;
    p.transmission = t * tint;
    p.thin_walled = thin;
    return p;
}

std::vector<std::pair<std::string, ClosureParams>> cases() {
    return {{"thin rough", glass(0.5f, true)},
            {"solid rough", glass(0.5f, false)},
            {"solid glossy", glass(0.2f, false)},
            {"thin half", glass(0.4f, true, 0.5f, Rgb(0.9f, 0.6f, 0.3f))},
            {"solid half", glass(0.6f, false, 0.5f, Rgb(0.9f, 0.6f, 0.3f))}};
}

Vec3 uniform_sphere(Rng& rng) {
    const float z = 1.0f - 2.0f * rng.next_float();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * rng.next_float();
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

TEST(BsdfTransmission, SampleAgreesWithPdfAndEvalOnBothSides) {
    for (const auto& [name, params] : cases()) {
        const Bsdf bsdf(params);
        ASSERT_TRUE(bsdf.transmits()) << name;
        Rng rng(3, 1);
        int transmitted = 0;
        for (int i = 0; i < 20000; ++i) {
            const Vec3 wo = uniform_sphere(rng);  // from outside and from inside
            const Vec2 u(rng.next_float(), rng.next_float());
            const std::optional<BsdfSample> s = bsdf.sample(wo, u, rng.next_float());
            if (!s) continue;
            if (s->wi.z * wo.z < 0.0f) ++transmitted;
            ASSERT_GT(s->pdf, 0.0f) << name;
            EXPECT_NEAR(glm::length(s->wi), 1.0f, 1e-5f) << name;
            EXPECT_NEAR(bsdf.pdf(wo, s->wi), s->pdf, 1e-4f * s->pdf) << name;
            const Rgb expected = bsdf.eval(wo, s->wi) * std::abs(s->wi.z) / s->pdf;
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(s->weight[k], expected[k], 1e-4f * expected[k] + 1e-7f) << name;
        }
        EXPECT_GT(transmitted, 2000) << name;
    }
}

// The energy light arriving from wo leaves with: ∫ f(wi, wo) |cos θi| dωi, the adjoint's albedo
// (Transport::Importance; radiance itself is not conserved across refraction, it scales by
// (η_o/η_i)²). By the BSDF's own samples (mean weight) and by uniform sphere samples
// (f |cos| · 4π): both unbiased, so they agree within 4σ of their difference, and the sampled one
// does not exceed 1 by more than 4σ for a white tint. Rough lobes only, where the uniform
// estimator's variance is small enough to mean something.
TEST(BsdfTransmission, EnergyAtMostOneAndEstimatorsAgree) {
    constexpr int kN = 40000;
    for (const auto& [name, params] : cases()) {
        ClosureParams white = params;
        white.base_color = Rgb(max_component(params.base_color) > 0.0f ? 0.5f : 0.0f);
        white.transmission = Rgb(max_component(params.transmission));
        const Bsdf bsdf(white);
        for (const float theta : {10.0f, 50.0f, 80.0f, 130.0f, 170.0f}) {
            const Vec3 wo = spherical_direction(theta * test::kDegree, 0.7f);
            Rng rng(11, uint64_t(theta));
            double s1 = 0, s2 = 0, u1 = 0, u2 = 0;
            for (int i = 0; i < kN; ++i) {
                const Vec2 u(rng.next_float(), rng.next_float());
                if (const auto s = bsdf.sample(wo, u, rng.next_float(), Transport::Importance)) {
                    const double w = luminance(s->weight);
                    s1 += w;
                    s2 += w * w;
                }
                const Vec3 wi = uniform_sphere(rng);
                const double f = luminance(bsdf.eval(wo, wi, Transport::Importance)) *
                                 std::abs(wi.z) * 4.0 * kPi;
                u1 += f;
                u2 += f * f;
            }
            const double ms = s1 / kN, mu = u1 / kN;
            const double vs = (s2 / kN - ms * ms) / kN, vu = (u2 / kN - mu * mu) / kN;
            EXPECT_LT(ms, 1.0 + 4.0 * std::sqrt(vs)) << name << " θ " << theta;
            EXPECT_LT(std::abs(ms - mu), 4.0 * std::sqrt(vs + vu) + 1e-4)
                << name << " θ " << theta << ": sampled " << ms << ", uniform " << mu;
        }
    }
}

// Thin sheets are reciprocal; refraction is in Walter et al.'s form f(o, i) / η_o² =
// f(i, o) / η_i² (their eq. 21's η_o²), and the adjoint (Importance) is f(i, o).
TEST(BsdfTransmission, ReciprocityAndAdjoint) {
    for (const auto& [name, params] : cases()) {
        const Bsdf bsdf(params);
        Rng rng(5, 2);
        for (int i = 0; i < 5000; ++i) {
            const Vec3 a = uniform_sphere(rng), b = uniform_sphere(rng);
            const float eta_a = params.thin_walled || a.z > 0.0f ? 1.0f : params.ior;
            const float eta_b = params.thin_walled || b.z > 0.0f ? 1.0f : params.ior;
            const Rgb ab = bsdf.eval(a, b) / (eta_a * eta_a);
            const Rgb ba = bsdf.eval(b, a) / (eta_b * eta_b);
            const Rgb adjoint = bsdf.eval(a, b, Transport::Importance);
            const Rgb reverse = bsdf.eval(b, a);
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(ab[k], ba[k], 1e-3f * std::max(ab[k], ba[k]) + 1e-7f) << name;
                EXPECT_NEAR(adjoint[k], reverse[k], 1e-3f * reverse[k] + 1e-7f) << name;
            }
        }
    }
}

// From inside a smooth solid past the critical angle (sin θ > 1/1.5, θ > 41.8°) every sample
// reflects back inside, with weight F = 1 times G2/G1 = 1 − O(α²): within 10⁻³ of 1.
TEST(BsdfTransmission, TotalInternalReflection) {
    const Bsdf bsdf(glass(0.0f, false));
    for (const float theta : {45.0f, 60.0f, 85.0f}) {
        const Vec3 wo = spherical_direction((180.0f - theta) * test::kDegree, 0.3f);  // inside
        Rng rng(1, uint64_t(theta));
        for (int i = 0; i < 2000; ++i) {
            const Vec2 u(rng.next_float(), rng.next_float());
            const auto s = bsdf.sample(wo, u, rng.next_float());
            ASSERT_TRUE(s.has_value()) << theta;
            EXPECT_LT(s->wi.z, 0.0f) << theta;  // stays inside
            EXPECT_NEAR(luminance(s->weight), 1.0f, 1e-3f) << theta;
        }
        // Transmitted directions carry only what GGX's tails let out: facets tilted by 3° or
        // more from the normal, where D(h) ≈ α² / (π θ⁴) ≈ 4 · 10⁻⁴ at most; f < 10⁻⁵ measured
        // ≤ 3 · 10⁻⁷.
        for (int i = 0; i < 200; ++i) {
            const Vec3 out = uniform_sphere(rng);
            if (out.z > 0.0f) {
                EXPECT_LT(max_component(bsdf.eval(wo, out)), 1e-5f) << theta;
            }
        }
    }
    // Below the critical angle light gets out, bent by Snell's law: sin θt = 1.5 sin θo.
    const Vec3 wo = spherical_direction((180.0f - 30.0f) * test::kDegree, 0.3f);
    Rng rng(2, 2);
    int out = 0;
    int bent = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec2 u(rng.next_float(), rng.next_float());
        const auto s = bsdf.sample(wo, u, rng.next_float());
        if (!s || s->wi.z < 0.0f) continue;
        ++out;
        const float sin_t = std::sqrt(1.0f - s->wi.z * s->wi.z);
        bent += std::abs(sin_t - 1.5f * std::sin(30.0f * test::kDegree)) < kSnellTolerance;
        EXPECT_NEAR(sin_t, 1.5f * std::sin(30.0f * test::kDegree), kTailTolerance);
    }
    EXPECT_GT(out, 1500);  // 1 − F ≈ 0.95 of the samples
    EXPECT_GT(bent, int(kWithinTolerance * float(out)));
}

// A smooth thin sheet passes light straight through with weight tint · (1 − F(cos θ)) (one
// interface: glTF's thin-walled BTDF) and reflects F; a smooth solid refracts by Snell's law with
// the same (1 − F). F is Schlick's with F0 = 0.04 (ior 1.5); α = 10⁻⁴ leaves G2/G1 within 10⁻⁶
// of 1. Directions: GGX's facets have heavy tails, P(θ_h > δ) = α² / (α² + tan² δ), so the
// bounds are on the share of samples: θ_h < 5 · 10⁻⁴ (direction within ~10⁻³ of the ideal one)
// for 1 − 0.04 of them, so at least 90 % (binomial 1000 or 2000 samples: > 8σ below 96 %); and
// every one within θ_h < 0.05 (probability 4 · 10⁻⁶ a sample of exceeding it).
TEST(BsdfTransmission, SmoothLimits) {
    const Rgb tint(0.9f, 0.7f, 0.5f);
    for (const bool thin : {true, false}) {
        const Bsdf bsdf(glass(0.0f, thin, 1.0f, tint));
        for (const float theta : {0.0f, 30.0f, 60.0f}) {
            const Vec3 wo = spherical_direction(theta * test::kDegree, 0.4f);
            const float f = fresnel_schlick(0.04f, 1.0f, std::cos(theta * test::kDegree));
            Rng rng(4, uint64_t(theta));
            int transmitted = 0;
            int straight = 0;
            for (int i = 0; i < 1000; ++i) {
                const Vec2 u(rng.next_float(), rng.next_float());
                const auto s = bsdf.sample(wo, u, rng.next_float());
                ASSERT_TRUE(s.has_value());
                const bool through = s->wi.z < 0.0f;
                transmitted += through;
                // The weight is the lobe's energy over the probability of having picked it;
                // radiance entering the solid is compressed by (1/1.5)².
                const float p_reflect = f / (f + luminance(tint) * (1.0f - f));
                const float eta2 = thin ? 1.0f : 1.5f * 1.5f;
                const Rgb expected =
                    through ? tint * (1.0f - f) / ((1.0f - p_reflect) * eta2) : Rgb(f / p_reflect);
                for (int k = 0; k < 3; ++k)
                    EXPECT_NEAR(s->weight[k], expected[k], 2e-3f);
                if (!through) continue;
                float error = 0.0f;
                if (thin) {
                    error = std::acos(std::min(1.0f, glm::dot(s->wi, -wo)));
                } else {
                    const float sin_t = std::sqrt(std::max(0.0f, 1.0f - s->wi.z * s->wi.z));
                    error = std::abs(sin_t - std::sin(theta * test::kDegree) / 1.5f);
                }
                straight += error < kSnellTolerance;
                EXPECT_LT(error, kTailTolerance);
            }
            EXPECT_GT(transmitted, 800);
            EXPECT_GT(straight, int(kWithinTolerance * float(transmitted)));
        }
    }
}

}  // namespace
}  // namespace mvpl::material
