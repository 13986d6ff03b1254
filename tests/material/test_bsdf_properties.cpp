// Properties of Bsdf that need no statistics: reciprocity, sample/pdf/eval consistency, the
// hemisphere rule, finiteness at extreme inputs, and agreement with the formulas written out
// independently (double precision, textbook forms) so the division-safe rewrites are checked.
#include <gtest/gtest.h>

#include "engine/core/rng.h"
#include "engine/material/bsdf.h"
#include "engine/material/microfacet.h"
#include "tests/material/bsdf_cases.h"
#include "tests/material/integrate.h"

namespace mvpl::material {
namespace {

using test::closure_zoo;
using test::uniform_hemisphere;

void expect_rgb_near(const Rgb& a, const Rgb& b, float relative, const std::string& what) {
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(a[k], b[k], relative * std::max(std::abs(a[k]), std::abs(b[k])) + 1e-7f)
            << what << " channel " << k;
    }
}

TEST(BsdfProperties, Reciprocity) {
    for (const auto& [name, params] : closure_zoo()) {
        const Bsdf bsdf(params);
        Rng rng(42, 0);
        for (int i = 0; i < 5000; ++i) {
            const Vec3 a = uniform_hemisphere(rng), b = uniform_hemisphere(rng);
            expect_rgb_near(bsdf.eval(a, b), bsdf.eval(b, a), 1e-4f, name);
        }
    }
}

TEST(BsdfProperties, SampleAgreesWithPdfAndEval) {
    for (const auto& [name, params] : closure_zoo()) {
        const Bsdf bsdf(params);
        Rng rng(7, 3);
        int produced = 0;
        for (int i = 0; i < 20000; ++i) {
            const Vec3 wo = uniform_hemisphere(rng);
            const Vec2 u(rng.next_float(), rng.next_float());
            const std::optional<BsdfSample> s = bsdf.sample(wo, u, rng.next_float());
            if (!s) continue;
            ++produced;
            ASSERT_GT(s->wi.z, 0.0f) << name;
            ASSERT_GT(s->pdf, 0.0f) << name;
            EXPECT_NEAR(glm::length(s->wi), 1.0f, 1e-5f) << name;
            // Same wi, same density: MIS in the path tracer depends on it.
            EXPECT_NEAR(bsdf.pdf(wo, s->wi), s->pdf, 1e-6f * s->pdf) << name;
            expect_rgb_near(s->weight, bsdf.eval(wo, s->wi) * s->wi.z / s->pdf, 1e-5f, name);
            EXPECT_GE(std::min({s->weight.r, s->weight.g, s->weight.b}), 0.0f) << name;
        }
        EXPECT_GT(produced, 10000) << name;
    }
}

// ∫ pdf over the hemisphere: 1 when no sample can fail (cosine lobes), at most 1 otherwise.
// Rough lobes are integrated over wi in (cos θ, φ), where the horizon is the domain's edge; narrow
// lobes over half vectors, ∫ pdf(wi(h)) · 4 (wo·h) dωh (Walter et al. 2007, eq. 14), where the
// peak sits around +z with a width of about alpha whatever wo is.
double pdf_integral(const Bsdf& bsdf, const Vec3& wo, float alpha) {
    if (alpha >= 0.1f) {
        const auto density = [&](double cos_theta, double phi) {
            const float s =
                static_cast<float>(std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta)));
            const float p = static_cast<float>(phi);
            return double(bsdf.pdf(wo, Vec3(s * std::cos(p), s * std::sin(p), float(cos_theta))));
        };
        return mvpl::test::integrate_2d(density, 0.0, 1.0, 0.0, 2.0 * M_PI, 1e-6, 4);
    }
    const auto density = [&](const Vec3& h) {
        const float cos_oh = glm::dot(wo, h);
        if (cos_oh <= 0.0f) return 0.0;
        return double(bsdf.pdf(wo, reflect_about(wo, h))) * 4.0 * cos_oh;
    };
    return mvpl::test::integrate_hemisphere(density, alpha, 1e-6);
}

TEST(BsdfProperties, PdfIntegratesToAtMostOne) {
    for (const auto& [name, params] : closure_zoo()) {
        const Bsdf bsdf(params);
        const float alpha = roughness_to_alpha(params.roughness);
        for (float theta : {0.0f, 40.0f, 75.0f}) {
            const double integral = pdf_integral(bsdf, test::outgoing(theta), alpha);
            EXPECT_LE(integral, 1.0 + 1e-4) << name << " theta " << theta;
            EXPECT_GT(integral, 0.3) << name << " theta " << theta;  // α = 1, θo = 0: exactly 0.5
            if (params.is_lambertian()) {
                EXPECT_NEAR(integral, 1.0, 1e-4) << name;
            }
        }
    }
}

TEST(BsdfProperties, NothingBelowTheSurface) {
    for (const auto& [name, params] : closure_zoo()) {
        const Bsdf bsdf(params);
        const Vec3 up = test::outgoing(30.0f);
        const Vec3 down(up.x, up.y, -up.z);
        const Vec3 horizon(1.0f, 0.0f, 0.0f);
        for (const auto& [wo, wi] :
             {std::pair{up, down}, std::pair{down, up}, std::pair{down, down},
              std::pair{horizon, up}, std::pair{up, horizon}, std::pair{up, -up}}) {
            EXPECT_EQ(bsdf.eval(wo, wi), Rgb(0.0f)) << name;
            EXPECT_EQ(bsdf.pdf(wo, wi), 0.0f) << name;
        }
        EXPECT_FALSE(bsdf.sample(down, Vec2(0.3f, 0.6f), 0.2f)) << name;
        EXPECT_FALSE(bsdf.sample(horizon, Vec2(0.3f, 0.6f), 0.7f)) << name;
    }
}

// Finite eval, pdf and sample for extreme roughness, grazing angles, the mirror and the
// anti-mirror configurations, and black and white base colours.
TEST(BsdfProperties, ExtremeInputsStayFinite) {
    Rng rng(5, 5);
    int checked = 0;
    for (float roughness : {0.0f, 1e-3f, 1e-2f, 0.5f, 1.0f}) {
        for (float metallic : {0.0f, 0.5f, 1.0f}) {
            for (float specular : {0.0f, 1.0f}) {
                for (float base : {0.0f, 1.0f}) {
                    ClosureParams p = test::dielectric(Rgb(base), roughness, 1.5f, specular);
                    p.metallic = metallic;
                    const Bsdf bsdf(p);
                    for (float cos_o : {1e-6f, 1e-4f, 0.01f, 0.5f, 1.0f}) {
                        const Vec3 wo(std::sqrt(1.0f - cos_o * cos_o), 0.0f, cos_o);
                        const Vec3 mirror(-wo.x, -wo.y, wo.z);
                        const Vec3 grazing(std::sqrt(1.0f - 1e-12f), 0.0f, 1e-6f);
                        for (const Vec3& wi :
                             {mirror, grazing, -wo, wo, Vec3(0, 0, 1), uniform_hemisphere(rng)}) {
                            const Rgb f = bsdf.eval(wo, wi);
                            const float density = bsdf.pdf(wo, wi);
                            ASSERT_TRUE(is_finite(f)) << roughness << " " << cos_o;
                            ASSERT_TRUE(std::isfinite(density)) << roughness << " " << cos_o;
                            EXPECT_GE(std::min({f.r, f.g, f.b}), 0.0f);
                            EXPECT_GE(density, 0.0f);
                            ++checked;
                        }
                        for (int i = 0; i < 64; ++i) {
                            const Vec2 u(rng.next_float(), rng.next_float());
                            const std::optional<BsdfSample> s =
                                bsdf.sample(wo, u, rng.next_float());
                            if (!s) continue;
                            ASSERT_TRUE(is_finite(s->wi) && is_finite(s->weight));
                            ASSERT_TRUE(std::isfinite(s->pdf) && s->pdf > 0.0f);
                        }
                        // The corners of the unit square.
                        for (const Vec2 u : {Vec2(0.0f), Vec2(0.0f, 0.99999994f),
                                             Vec2(0.99999994f, 0.0f), Vec2(0.99999994f)}) {
                            for (const float ul : {0.0f, 0.5f, 0.99999994f}) {
                                if (const auto s = bsdf.sample(wo, u, ul)) {
                                    ASSERT_TRUE(is_finite(s->wi) && is_finite(s->weight));
                                    ASSERT_TRUE(std::isfinite(s->pdf) && s->pdf > 0.0f);
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    EXPECT_GT(checked, 1000);
}

TEST(BsdfProperties, NaNAndOutOfRangeParametersAreClamped) {
    ClosureParams p;
    p.base_color = Rgb(std::nanf(""), 2.0f, -1.0f);
    p.metallic = std::nanf("");
    p.roughness = -3.0f;
    p.specular = 5.0f;
    p.specular_color = Rgb(std::numeric_limits<float>::infinity());
    p.ior = std::numeric_limits<float>::infinity();
    const Bsdf bsdf(p);
    Rng rng(1, 1);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 wo = uniform_hemisphere(rng), wi = uniform_hemisphere(rng);
        ASSERT_TRUE(is_finite(bsdf.eval(wo, wi)));
        ASSERT_TRUE(std::isfinite(bsdf.pdf(wo, wi)));
        if (const auto s = bsdf.sample(wo, Vec2(rng.next_float(), rng.next_float()), 0.5f)) {
            ASSERT_TRUE(is_finite(s->weight));
        }
    }
}

// The Lambertian fast path is the limit of the general model as the layer vanishes.
TEST(BsdfProperties, LambertianFastPathIsTheLimitOfTheLayeredModel) {
    const Rgb base(0.3f, 0.6f, 0.9f);
    const Bsdf fast(test::lambertian(base));
    ASSERT_TRUE(fast.params().is_lambertian());
    const Bsdf layered(test::dielectric(base, 0.5f, 1.5f, 1e-6f));
    Rng rng(3, 3);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 wo = uniform_hemisphere(rng), wi = uniform_hemisphere(rng);
        expect_rgb_near(fast.eval(wo, wi), base / kPi, 1e-6f, "fast path");
        expect_rgb_near(layered.eval(wo, wi), base / kPi, 1e-4f, "layered");
        EXPECT_NEAR(fast.pdf(wo, wi), wi.z / kPi, 1e-6f);
    }
    const std::optional<BsdfSample> s = fast.sample(test::outgoing(20.0f), Vec2(0.3f, 0.8f), 0.9f);
    ASSERT_TRUE(s);
    expect_rgb_near(s->weight, base, 1e-5f, "fast path weight");
}

// glTF: material = mix(dielectric_brdf, metal_brdf, metallic).
TEST(BsdfProperties, MetallicMixesLinearly) {
    const Rgb base(0.9f, 0.5f, 0.1f);
    const Bsdf dielectric(test::mixture(base, 0.4f, 0.0f));
    const Bsdf metal(test::mixture(base, 0.4f, 1.0f));
    const Bsdf half(test::mixture(base, 0.4f, 0.5f));
    Rng rng(8, 8);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 wo = uniform_hemisphere(rng), wi = uniform_hemisphere(rng);
        expect_rgb_near(half.eval(wo, wi), 0.5f * (dielectric.eval(wo, wi) + metal.eval(wo, wi)),
                        1e-5f, "metallic 0.5");
    }
}

// ---- The formulas, written out in double precision in their textbook form. ----

double textbook_d(const glm::dvec3& h, double alpha) {  // Walter et al. 2007, eq. 33
    const double c2 = h.z * h.z, a2 = alpha * alpha, tan2 = (1.0 - c2) / c2;
    return a2 / (M_PI * c2 * c2 * (a2 + tan2) * (a2 + tan2));
}
double textbook_lambda(const glm::dvec3& w, double alpha) {  // Heitz 2014, eq. 72
    const double tan2 = (1.0 - w.z * w.z) / (w.z * w.z);
    return 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}
glm::dvec3 schlick(const glm::dvec3& f0, const glm::dvec3& f90, double c) {
    return f0 + (f90 - f0) * std::pow(1.0 - std::abs(c), 5.0);
}

glm::dvec3 textbook_gltf(const ClosureParams& p, const glm::dvec3& wo, const glm::dvec3& wi) {
    const double alpha = std::max(double(p.roughness) * p.roughness, double(kMinAlpha));
    const glm::dvec3 h = glm::normalize(wo + wi);
    const double g2 = 1.0 / (1.0 + textbook_lambda(wo, alpha) + textbook_lambda(wi, alpha));
    const double spec = textbook_d(h, alpha) * g2 / (4.0 * wo.z * wi.z);
    const double voh = glm::dot(wo, h);
    const glm::dvec3 base(p.base_color);
    // KHR_materials_specular + KHR_materials_ior.
    const double f0_ior = std::pow((p.ior - 1.0) / (p.ior + 1.0), 2.0);
    const glm::dvec3 f0 =
        glm::min(f0_ior * glm::dvec3(p.specular_color), glm::dvec3(1.0)) * double(p.specular);
    const glm::dvec3 f90(p.specular);
    const double f0_max = std::max({f0.x, f0.y, f0.z});
    const auto max_f = [&](double c) {
        return f0_max + (p.specular - f0_max) * std::pow(1 - c, 5);
    };
    const glm::dvec3 dielectric =
        schlick(f0, f90, voh) * spec + (1.0 - max_f(wo.z)) * (1.0 - max_f(wi.z)) * base / M_PI;
    const glm::dvec3 metal = schlick(base, glm::dvec3(1.0), voh) * spec;
    return (1.0 - p.metallic) * dielectric + double(p.metallic) * metal;
}

TEST(BsdfProperties, MatchesTheDocumentedFormulas) {
    for (const auto& [name, params] : closure_zoo()) {
        if (params.is_lambertian()) continue;
        const Bsdf bsdf(params);
        Rng rng(77, 1);
        for (int i = 0; i < 3000; ++i) {
            const Vec3 wo = uniform_hemisphere(rng), wi = uniform_hemisphere(rng);
            // Away from the horizon, where float and double forms agree to many digits.
            if (wo.z < 0.02f || wi.z < 0.02f || glm::length(wo + wi) < 0.05f) continue;
            const glm::dvec3 ref = textbook_gltf(params, glm::dvec3(wo), glm::dvec3(wi));
            expect_rgb_near(bsdf.eval(wo, wi), Rgb(ref), 2e-3f, name);
        }
    }
}

TEST(BsdfProperties, LobeProbability) {
    const Vec3 wo = test::outgoing(30.0f);
    EXPECT_EQ(Bsdf(test::lambertian(Rgb(0.5f))).specular_probability(wo), 0.0f);
    EXPECT_EQ(Bsdf(test::conductor(Rgb(0.5f), 0.3f)).specular_probability(wo), 1.0f);
    // Black base: only the layer reflects.
    EXPECT_EQ(Bsdf(test::dielectric(Rgb(0.0f), 0.3f)).specular_probability(wo), 1.0f);
    for (const float theta : {0.0f, 45.0f, 80.0f, 89.9f}) {
        for (const float metallic : {0.0f, 0.3f, 0.9f}) {
            const float p = Bsdf(test::mixture(Rgb(0.5f), 0.3f, metallic))
                                .specular_probability(test::outgoing(theta));
            EXPECT_GE(p, 0.1f);
            EXPECT_LE(p, 0.9f);
        }
    }
    // More specular towards grazing angles, where the Fresnel term rises.
    const Bsdf plastic(test::dielectric(Rgb(0.5f), 0.3f));
    EXPECT_LT(plastic.specular_probability(test::outgoing(0.0f)),
              plastic.specular_probability(test::outgoing(85.0f)));
}

}  // namespace
}  // namespace mvpl::material
