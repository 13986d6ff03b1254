// GGX building blocks: normalisation of D and of the visible-normal distribution, the Smith
// identities, and the alpha clamp.
#include <gtest/gtest.h>

#include "engine/core/rng.h"
#include "engine/material/microfacet.h"
#include "tests/material/bsdf_cases.h"
#include "tests/material/integrate.h"

namespace mvpl::material {
namespace {

double integrate_hemisphere(const std::function<double(const Vec3&)>& g, float alpha) {
    return mvpl::test::integrate_hemisphere(g, alpha);
}

TEST(Microfacet, RoughnessToAlphaSquaresAndClamps) {
    EXPECT_FLOAT_EQ(roughness_to_alpha(0.5f), 0.25f);
    EXPECT_FLOAT_EQ(roughness_to_alpha(1.0f), 1.0f);
    EXPECT_FLOAT_EQ(roughness_to_alpha(3.0f), 1.0f);
    EXPECT_FLOAT_EQ(roughness_to_alpha(1e-3f), kMinAlpha);  // alpha 1e-6 is clamped
    EXPECT_FLOAT_EQ(roughness_to_alpha(0.0f), kMinAlpha);
    EXPECT_FLOAT_EQ(roughness_to_alpha(-1.0f), kMinAlpha);
}

// Walter et al. 2007, eq. 4: ∫ D(h) cos θh dωh = 1 (projected microfacet area = macro area).
TEST(Microfacet, DistributionIsNormalised) {
    for (float alpha : {kMinAlpha, 0.01f, 0.1f, 0.5f, 1.0f}) {
        const double integral =
            integrate_hemisphere([alpha](const Vec3& h) { return ggx_d(h, alpha) * h.z; }, alpha);
        EXPECT_NEAR(integral, 1.0, 1e-4) << "alpha " << alpha;
    }
}

// Heitz 2018, eq. 2: ∫ D_wo(h) dωh = 1 for every wo (the visible projected area is cos θo).
TEST(Microfacet, VisibleNormalDistributionIsNormalised) {
    for (float alpha : {0.01f, 0.1f, 0.5f, 1.0f}) {
        for (float theta_deg : {0.0f, 30.0f, 60.0f, 85.0f}) {
            const Vec3 wo = test::outgoing(theta_deg);
            const double integral = integrate_hemisphere(
                [&](const Vec3& h) { return ggx_visible_normal_pdf(wo, h, alpha); }, alpha);
            EXPECT_NEAR(integral, 1.0, 1e-3) << "alpha " << alpha << " theta " << theta_deg;
        }
    }
}

TEST(Microfacet, SmithTermsAreConsistent) {
    Rng rng(7, 1);
    for (int i = 0; i < 2000; ++i) {
        const float alpha = std::max(rng.next_float(), kMinAlpha);
        const Vec3 wo = test::uniform_hemisphere(rng);
        const Vec3 wi = test::uniform_hemisphere(rng);
        if (wo.z < 1e-3f || wi.z < 1e-3f) continue;
        const float g1o = ggx_g1(wo, alpha), g1i = ggx_g1(wi, alpha);
        EXPECT_NEAR(g1o, 1.0f / (1.0f + ggx_lambda(wo, alpha)), 1e-5f);
        // Heitz 2014, eq. 99, and the bounds of the height-correlated form between the
        // uncorrelated product and the smaller of the two G1.
        const float g2 = ggx_g2(wo, wi, alpha);
        EXPECT_NEAR(g2, 1.0f / (1.0f + ggx_lambda(wo, alpha) + ggx_lambda(wi, alpha)), 1e-5f);
        EXPECT_GE(g2, g1o * g1i - 1e-6f);
        EXPECT_LE(g2, std::min(g1o, g1i) + 1e-6f);
        EXPECT_NEAR(ggx_visibility(wo, wi, alpha) * 4.0f * wo.z * wi.z, g2, 1e-4f * g2 + 1e-6f);
        // Λ against its textbook form with tan θ (Heitz 2014, eq. 72).
        const double tan2 = (1.0 - double(wo.z) * wo.z) / (double(wo.z) * wo.z);
        const double lambda = 0.5 * (std::sqrt(1.0 + double(alpha) * alpha * tan2) - 1.0);
        EXPECT_NEAR(ggx_lambda(wo, alpha), lambda, 1e-4 * lambda + 1e-5);
    }
}

TEST(Microfacet, DistributionMatchesTextbookForm) {
    Rng rng(3, 4);
    for (int i = 0; i < 2000; ++i) {
        const float alpha = std::max(rng.next_float(), 0.01f);
        const Vec3 h = test::uniform_hemisphere(rng);
        if (h.z < 1e-2f) continue;
        // Walter et al. 2007, eq. 33.
        const double c2 = double(h.z) * h.z, a2 = double(alpha) * alpha;
        const double tan2 = (1.0 - c2) / c2;
        const double d = a2 / (M_PI * c2 * c2 * (a2 + tan2) * (a2 + tan2));
        EXPECT_NEAR(ggx_d(h, alpha), d, 1e-4 * d);
    }
}

// The reflection pdf is D_wo(h) / (4 wo·h) (Walter et al. 2007, eq. 14).
TEST(Microfacet, ReflectionPdfIsVisibleNormalPdfTimesJacobian) {
    Rng rng(11, 2);
    for (int i = 0; i < 2000; ++i) {
        const float alpha = std::max(rng.next_float(), kMinAlpha);
        const Vec3 wo = test::uniform_hemisphere(rng);
        const Vec3 wi = test::uniform_hemisphere(rng);
        const Vec3 h = glm::normalize(wo + wi);
        const float expected = ggx_visible_normal_pdf(wo, h, alpha) / (4.0f * glm::dot(wo, h));
        EXPECT_NEAR(ggx_reflection_pdf(wo, wi, alpha), expected, 1e-4f * expected);
    }
}

TEST(Microfacet, VisibleNormalSamplesFaceTheViewer) {
    Rng rng(5, 9);
    for (float alpha : {kMinAlpha, 0.01f, 0.3f, 1.0f}) {
        for (float cos_o : {1e-6f, 1e-3f, 0.2f, 0.7f, 1.0f}) {
            const Vec3 wo(std::sqrt(1.0f - cos_o * cos_o), 0.0f, cos_o);
            for (int i = 0; i < 500; ++i) {
                const Vec3 h =
                    ggx_sample_visible_normal(wo, alpha, Vec2(rng.next_float(), rng.next_float()));
                ASSERT_TRUE(is_finite(h));
                EXPECT_NEAR(glm::length(h), 1.0f, 1e-5f);
                EXPECT_GE(h.z, 0.0f);
                EXPECT_GE(glm::dot(wo, h), -1e-5f);
            }
        }
    }
}

}  // namespace
}  // namespace mvpl::material
