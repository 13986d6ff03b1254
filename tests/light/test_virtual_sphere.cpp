// Virtual spherical lights in closed form (shaders/shared/virtual_sphere.h,
// light::widen_closure): the widened GGX lobe gives the point lobe back as the sphere shrinks,
// reflects no more energy than a BRDF may, and stays close to the definition it replaces (Hašan
// et al. 2009): the point lobe averaged over the cone of directions the sphere fills.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/core/math.h"
#include "engine/core/rng.h"
#include "engine/light/virtual_sphere.h"
#include "engine/material/bsdf.h"
#include "shaders/shared/virtual_sphere.h"

namespace mvpl::light {
namespace {

material::ClosureParams metal(float roughness) {
    material::ClosureParams p;
    p.base_color = Rgb(1.0f);  // F = 1: the lobe's albedo is its microfacet term's alone
    p.metallic = 1.0f;
    p.roughness = roughness;
    return p;
}

material::ClosureParams plastic(float roughness) {
    material::ClosureParams p;
    p.base_color = Rgb(0.9f, 0.2f, 0.1f);
    p.metallic = 0.0f;
    p.roughness = roughness;
    return p;
}

Vec3 direction(float theta, float phi) {
    return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

// ∫ f(wo, wi) cos θi dωi by the midpoint rule on a θ × φ grid of the hemisphere.
double albedo(const material::Bsdf& bsdf, const Vec3& wo, int n_theta, int n_phi) {
    double sum = 0.0;
    const double d_theta = 0.5 * kPi / n_theta;
    const double d_phi = 2.0 * kPi / n_phi;
    for (int i = 0; i < n_theta; ++i) {
        const double theta = (i + 0.5) * d_theta;
        for (int j = 0; j < n_phi; ++j) {
            const Vec3 wi = direction(float(theta), float((j + 0.5) * d_phi));
            sum += double(bsdf.eval(wo, wi).r) * std::cos(theta) * std::sin(theta);
        }
    }
    return sum * d_theta * d_phi;
}

// r → 0: vsl_spread2 → 0 as (r/2d)², and the widened lobe is the point lobe. D = α² / (π (sin²θh
// + α² cos²θh)²) changes by at most a relative s²/α² (d ln D / dα² ≤ 1/α², off the peak), which
// is 1.6e-6 for r/d = 10⁻⁴ and α ≥ 0.04, plus the float round trip α → √α → α (a few ulp,
// ~1e-6 relative in D): 1e-4 leaves over an order of magnitude of margin.
TEST(VirtualSphere, AVanishingSphereIsThePointLobe) {
    EXPECT_EQ(shared::vsl_spread2(0.0f, 1.0f), 0.0f);
    const material::ClosureParams p = metal(0.3f);
    const material::ClosureParams same = widen_closure(p, 0.0f);
    EXPECT_EQ(same.roughness, p.roughness);
    const float d = 2.0f;
    const float r = 1e-4f * d;
    const float spread2 = shared::vsl_spread2(r * r, d * d);
    EXPECT_NEAR(spread2, 0.25f * 1e-8f, 1e-14f);
    for (const material::ClosureParams& c : {metal(0.2f), metal(0.5f), plastic(0.3f)}) {
        const material::Bsdf point(c);
        const material::Bsdf sphere(widen_closure(c, spread2));
        const Vec3 wo = glm::normalize(Vec3(0.3f, -0.1f, 0.9f));
        for (float phi : {0.0f, 0.5f, 3.0f}) {
            for (float theta : {0.1f, 0.4f, 0.9f}) {
                const Vec3 wi = direction(theta, phi);
                const Rgb a = point.eval(wo, wi);
                const Rgb b = sphere.eval(wo, wi);
                for (int k = 0; k < 3; ++k)
                    EXPECT_NEAR(b[k], a[k], 1e-4f * a[k]) << c.roughness << " " << theta;
            }
        }
    }
    // Lambertian closures are left as they are.
    material::ClosureParams diffuse;
    diffuse.metallic = 0.0f;
    diffuse.specular = 0.0f;
    diffuse.roughness = 0.3f;
    EXPECT_EQ(widen_closure(diffuse, 0.1f).roughness, 0.3f);
}

// Energy: a white conductor's albedo ∫ f cos dω is ≤ 1 for every sphere, widened or not. The
// midpoint rule on a 1024 × 512 grid resolves lobes of α' ≥ 0.05 (≥ 30 cells across): halving
// both resolutions changes the albedo by < 1e-3 (measured), so 1 + 2e-3 bounds a lobe whose
// true albedo is ≤ 1. The widened lobe also never reflects more than the point lobe plus that
// error: roughening only moves energy to grazing directions where shadowing removes it.
TEST(VirtualSphere, TheWidenedLobeConservesEnergy) {
    for (float roughness : {0.25f, 0.5f, 0.8f}) {
        const material::ClosureParams c = metal(roughness);
        for (float theta_o : {0.0f, 0.8f, 1.3f}) {
            const Vec3 wo = direction(theta_o, 0.0f);
            const double base = albedo(material::Bsdf(c), wo, 1024, 512);
            for (float spread2 : {0.0025f, 0.02f, 0.25f}) {
                const material::Bsdf sphere(widen_closure(c, spread2));
                const double a = albedo(sphere, wo, 1024, 512);
                const double coarse = albedo(sphere, wo, 512, 256);
                EXPECT_LT(std::abs(a - coarse), 1e-3) << roughness << " " << theta_o;
                EXPECT_LE(a, 1.0 + 2e-3) << roughness << " " << theta_o << " " << spread2;
                EXPECT_LE(a, base + 2e-3) << roughness << " " << theta_o << " " << spread2;
            }
        }
    }
}

// Against the definition (Hašan et al. 2009, eq. 3): the point lobe averaged over the cone of
// half-angle θs = asin(r/d) that the sphere fills, at the cone's centre, where a point VPL's
// spike sits. The closed form matches a mirror's average exactly by construction (α' = θs/2,
// virtual_sphere.h); for α between 0.04 and 0.25 and θs up to 0.4 rad the measured ratio
// (closed form / cone average) lies in [0.996, 1.16] (docs/results.md) — within a factor 1.5 is
// the bound, far from the factor (1 + θs²/(4α²)) = 26 by which the point lobe's spike exceeds
// the closed form's at α = 0.04, θs = 0.4.
TEST(VirtualSphere, TheWidenedLobeMatchesTheConeAverageAtItsCentre) {
    Rng rng(7, 0);
    for (float roughness : {0.2f, 0.35f, 0.5f}) {
        const material::ClosureParams c = metal(roughness);
        const float alpha = roughness * roughness;
        const Vec3 wo = direction(0.5f, 0.0f);
        const Vec3 centre = direction(0.5f, kPi);  // the mirror direction: the lobe's peak
        const Frame frame(centre);
        for (float theta_s : {0.1f, 0.2f, 0.4f}) {
            // Uniform directions in the cone (solid angle 2π(1 − cos θs)), stratified in
            // (cos, φ): 256 × 256 strata.
            double sum = 0.0;
            int count = 0;
            const material::Bsdf point(c);
            const int n = 256;
            for (int i = 0; i < n; ++i) {
                for (int j = 0; j < n; ++j) {
                    const float u = (float(i) + rng.next_float()) / float(n);
                    const float v = (float(j) + rng.next_float()) / float(n);
                    const float cos_t = 1.0f - u * (1.0f - std::cos(theta_s));
                    const float sin_t = std::sqrt(std::max(0.0f, 1.0f - cos_t * cos_t));
                    const float phi = 2.0f * kPi * v;
                    const Vec3 w =
                        frame.to_world(Vec3(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t));
                    sum += double(point.eval(wo, w).r);
                    ++count;
                }
            }
            const double average = sum / count;
            const float d = 1.0f;
            const float r = std::sin(theta_s) * d;
            const material::Bsdf sphere(widen_closure(c, shared::vsl_spread2(r * r, d * d)));
            const double closed = double(sphere.eval(wo, centre).r);
            const double ratio = closed / average;
            std::printf(
                "alpha %.3f theta_s %.2f: closed form %.4g, cone average %.4g, ratio %.3f\n", alpha,
                theta_s, closed, average, ratio);
            EXPECT_GT(ratio, 1.0 / 1.5) << alpha << " " << theta_s;
            EXPECT_LT(ratio, 1.5) << alpha << " " << theta_s;
        }
    }
}

}  // namespace
}  // namespace mvpl::light
