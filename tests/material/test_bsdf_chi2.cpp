// Chi-square goodness-of-fit of Bsdf::sample against Bsdf::pdf (see chi2.h), one test per closure
// and outgoing direction, Šidák-corrected so that the whole family has significance 1e-3.
#include <gtest/gtest.h>

#include "engine/core/rng.h"
#include "engine/core/sampling.h"
#include "engine/material/bsdf.h"
#include "tests/material/bsdf_cases.h"
#include "tests/material/chi2.h"

namespace mvpl::material {
namespace {

struct Chi2Case {
    std::string name;
    ClosureParams params;
    float theta_o_deg;
};

void PrintTo(const Chi2Case& c, std::ostream* os) {
    *os << c.name << "@" << c.theta_o_deg;
}

std::vector<Chi2Case> chi2_cases() {
    using namespace test;
    const Rgb grey(0.7f);
    std::vector<Chi2Case> cases;
    for (float theta : {0.0f, 45.0f, 80.0f}) {
        cases.push_back({"lambertian", lambertian(grey), theta});
    }
    for (float r : {0.1f, 0.3f, 0.7f}) {
        for (float theta : {0.0f, 30.0f, 60.0f, 85.0f}) {
            cases.push_back({"conductor_r" + std::to_string(r).substr(0, 3),
                             conductor(Rgb(0.9f, 0.6f, 0.5f), r), theta});
        }
    }
    for (float theta : {10.0f, 50.0f, 80.0f}) {
        cases.push_back({"dielectric_r0.2", dielectric(Rgb(0.2f, 0.5f, 0.8f), 0.2f), theta});
        cases.push_back({"dielectric_r0.6", dielectric(grey, 0.6f), theta});
        cases.push_back({"mixture_m0.5_r0.3", mixture(Rgb(0.8f, 0.4f, 0.3f), 0.3f, 0.5f), theta});
    }
    cases.push_back({"dielectric_spec0.5_colored",
                     dielectric(grey, 0.4f, 1.7f, 0.5f, Rgb(1.2f, 0.8f, 0.3f)), 40.0f});
    cases.push_back({"mixture_m0.2_r0.15", mixture(Rgb(0.5f), 0.15f, 0.2f), 65.0f});
    return cases;
}

const std::vector<Chi2Case>& all_cases() {
    static const std::vector<Chi2Case> cases = chi2_cases();
    return cases;
}

class SamplerChi2 : public testing::TestWithParam<Chi2Case> {};

TEST_P(SamplerChi2, SampleMatchesPdf) {
    const Chi2Case& c = GetParam();
    const Bsdf bsdf(c.params);
    const Vec3 wo = test::outgoing(c.theta_o_deg);
    Rng rng(1234, static_cast<uint64_t>(c.theta_o_deg * 10.0f) + 1);
    const auto sample = [&]() -> std::optional<Vec3> {
        const Vec2 u(rng.next_float(), rng.next_float());
        const std::optional<BsdfSample> s = bsdf.sample(wo, u, rng.next_float());
        if (!s) return std::nullopt;
        return s->wi;
    };
    const auto pdf = [&](const Vec3& wi) { return static_cast<double>(bsdf.pdf(wo, wi)); };

    mvpl::test::Chi2Config config;
    config.significance =
        mvpl::test::sidak_significance(1e-3, static_cast<int>(all_cases().size()));
    const mvpl::test::Chi2Result result = mvpl::test::run_chi2_test(sample, pdf, config);
    EXPECT_TRUE(result.passed) << result.message;
    RecordProperty("chi2", result.message);
    // The density integrates to 1 minus the share of samples that fail (rays leaving the
    // hemisphere), never to more.
    EXPECT_LE(result.pdf_integral, 1.0 + 1e-4);
    if (c.params.is_lambertian()) {
        EXPECT_NEAR(result.pdf_integral, 1.0, 1e-4);
    }
}

std::string case_name(const testing::TestParamInfo<Chi2Case>& info) {
    std::string s = info.param.name + "_theta" + std::to_string(int(info.param.theta_o_deg));
    for (char& ch : s) {
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    }
    return s;
}

INSTANTIATE_TEST_SUITE_P(Closures, SamplerChi2, testing::ValuesIn(all_cases()), case_name);

// The test itself: it must reject a sampler whose pdf is wrong (cosine samples claimed to be
// uniform on the hemisphere) and accept the right one.
TEST(Chi2Helper, RejectsWrongPdfAndAcceptsRightOne) {
    Rng rng(9, 9);
    const auto sample = [&]() -> std::optional<Vec3> {
        return sample_cosine_hemisphere(Vec2(rng.next_float(), rng.next_float()));
    };
    mvpl::test::Chi2Config config;
    config.sample_count = 200000;
    const auto right = [](const Vec3& w) { return w.z > 0.0f ? double(w.z) / M_PI : 0.0; };
    const auto wrong = [](const Vec3& w) { return w.z > 0.0f ? 0.5 / M_PI : 0.0; };
    EXPECT_TRUE(mvpl::test::run_chi2_test(sample, right, config).passed);
    rng = Rng(9, 9);
    EXPECT_FALSE(mvpl::test::run_chi2_test(sample, wrong, config).passed);
}

TEST(Chi2Helper, SurvivalFunctionMatchesKnownQuantiles) {
    // χ²(1) at 3.841 and χ²(10) at 18.307 have upper tails 0.05; χ²(100) at 135.807 has 0.01.
    EXPECT_NEAR(mvpl::test::chi2_survival(3.841459, 1), 0.05, 1e-5);
    EXPECT_NEAR(mvpl::test::chi2_survival(18.307038, 10), 0.05, 1e-5);
    EXPECT_NEAR(mvpl::test::chi2_survival(135.806723, 100), 0.01, 1e-5);
    EXPECT_NEAR(mvpl::test::sidak_significance(0.05, 1), 0.05, 1e-12);
    EXPECT_NEAR(mvpl::test::sidak_significance(1e-3, 10), 1.0 - std::pow(0.999, 0.1), 1e-12);
}

}  // namespace
}  // namespace mvpl::material
