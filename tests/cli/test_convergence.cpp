// `mvpl convergence` (issue 6): the fits it draws its conclusions from recover known constants,
// and a tiny run on the Cornell box writes a CSV in which every method's error falls with time.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

#include "tests/cli/run_command.h"
#include "tools/cli/convergence_analysis.h"

namespace mvpl {
namespace {

using cli::ConvergencePoint;

std::vector<ConvergencePoint> curve(const std::string& method, double floor, double c) {
    std::vector<ConvergencePoint> points;
    for (double t = 0.25; t <= 64.0; t *= 2.0) {
        ConvergencePoint p;
        p.method = method;
        p.seconds = t;
        p.rel_mse = floor + c / t;
        points.push_back(p);
    }
    return points;
}

// Exact data: the fits are closed-form least squares, so they recover the constants to rounding.
TEST(ConvergenceAnalysis, InverseTimeConstantOfAnExactCurve) {
    EXPECT_NEAR(cli::inverse_time_constant(curve("pt", 0.0, 0.37)), 0.37, 1e-12);
    EXPECT_EQ(cli::inverse_time_constant({}), 0.0);
}

TEST(ConvergenceAnalysis, FloorFitRecoversFloorAndSlope) {
    const cli::FloorFit fit = cli::fit_floor(curve("mc", 0.013, 0.2));
    EXPECT_NEAR(fit.floor, 0.013, 1e-12);
    EXPECT_NEAR(fit.c, 0.2, 1e-12);
}

// A measured curve starts with points that start-up dominates (here 10× the model): relative
// residuals keep them from pulling the floor off the plateau that the long runs reach.
TEST(ConvergenceAnalysis, FloorFitFollowsThePlateauDespiteAStartUpOutlier) {
    std::vector<ConvergencePoint> points = curve("mc", 0.0023, 0.01);
    points.front().rel_mse *= 10.0;
    const cli::FloorFit fit = cli::fit_floor(points);
    EXPECT_NEAR(fit.floor, 0.0023, 0.1 * 0.0023);
}

TEST(ConvergenceAnalysis, FloorIsNeverNegativeNorTheSlopeRising) {
    // An unbiased curve with a little downward bend would fit a negative floor: it is clamped to 0.
    std::vector<ConvergencePoint> points = curve("mc", 0.0, 0.5);
    points.back().rel_mse *= 0.5;
    const cli::FloorFit unbiased = cli::fit_floor(points);
    EXPECT_EQ(unbiased.floor, 0.0);
    EXPECT_GT(unbiased.c, 0.0);
    // Error that grows with time has no 1/t part: it is all floor (the mean).
    const cli::FloorFit rising = cli::fit_floor(curve("mc", 1.0, -0.1));
    EXPECT_EQ(rising.c, 0.0);
    EXPECT_GT(rising.floor, 0.0);
}

TEST(ConvergenceAnalysis, PointsOfOneMethodInTimeOrderAndCsv) {
    std::vector<ConvergencePoint> all = curve("mc", 0.0, 1.0);
    std::vector<ConvergencePoint> pt = curve("pt", 0.0, 1.0);
    all.insert(all.begin(), pt.rbegin(), pt.rend());
    const std::vector<ConvergencePoint> sorted = cli::points_of(all, "pt");
    ASSERT_EQ(sorted.size(), pt.size());
    for (size_t i = 1; i < sorted.size(); ++i)
        EXPECT_LT(sorted[i - 1].seconds, sorted[i].seconds);
    const std::string csv = cli::to_csv(all);
    EXPECT_EQ(csv.rfind("method,seconds,samples,rel_mse,rmse,mean_ratio\n", 0), 0u);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), static_cast<long>(all.size() + 1));
}

struct CsvRow {
    double seconds, samples, rel_mse, rmse, mean_ratio;
};

std::map<std::string, std::vector<CsvRow>> read_csv(const std::filesystem::path& path) {
    std::map<std::string, std::vector<CsvRow>> rows;
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream fields(line);
        std::string method;
        CsvRow r{};
        fields >> method >> r.seconds >> r.samples >> r.rel_mse >> r.rmse >> r.mean_ratio;
        EXPECT_FALSE(fields.fail()) << line;
        rows[method].push_back(r);
    }
    return rows;
}

// A 16² reference with 1024 spp, then 3 s per method. The path tracer's first point has one spp
// and its last ≥ 8× as many (a 16² pass takes about a millisecond, even under the sanitizers), so
// its relMSE must fall (variance ∝ 1/spp; an 8× drop in expectation leaves no room for noise to
// reverse it), and with ≥ 1024 spp its mean is the reference's within 10% (its relMSE is then
// ~1e-3, i.e. ~3% per pixel, far less over 256 pixels). How many points the VPL samplers reach
// depends on the machine (the Metropolis sampler's bootstrap alone can take the whole budget on a
// loaded one), so for them only the points' values and the budget rule are checked: every point
// after the first starts before the budget is spent.
TEST(ConvergenceCli, TinyRunWritesFallingCurves) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("mvpl_conv_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string ref = (dir / "ref.exr").string();
    const std::string scene = MVPL_ASSETS_DIR "/cornell-box/cbox.gltf";
    ASSERT_EQ(test::run_mvpl("reference " + scene + " --res 16x16 --spp 1024 --quiet -o " + ref)
                  .exit_code,
              0);
    constexpr double kBudget = 3.0;
    const test::CommandResult r =
        test::run_mvpl_gpu("convergence " + scene + " --ref " + ref + " --budget 3 --shadow-res " +
                           "16 --no-plot --out " + test::shell_quote(dir.string()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("bias floor"), std::string::npos) << r.out;
    const auto rows = read_csv(dir / "convergence.csv");
    for (const char* method : {"pt", "mc", "metropolis"}) {
        SCOPED_TRACE(method);
        ASSERT_TRUE(rows.count(method));
        const std::vector<CsvRow>& m = rows.at(method);
        ASSERT_GE(m.size(), 1u);
        for (size_t i = 0; i < m.size(); ++i) {
            EXPECT_TRUE(std::isfinite(m[i].rel_mse) && m[i].rel_mse > 0.0);
            EXPECT_TRUE(std::isfinite(m[i].mean_ratio) && m[i].mean_ratio > 0.0);
            EXPECT_GT(m[i].samples, 0.0);
            if (i > 0) {
                EXPECT_GT(m[i].samples, m[i - 1].samples);
                EXPECT_GT(m[i].seconds, m[i - 1].seconds);
                EXPECT_LT(m[i - 1].seconds, kBudget);
            }
        }
        if (std::string(method) == "pt") {
            ASSERT_GE(m.size(), 4u);
            EXPECT_GE(m.back().samples, 8.0 * m.front().samples);
            EXPECT_LT(m.back().rel_mse, m.front().rel_mse);
            if (m.back().samples >= 1024) {
                EXPECT_NEAR(m.back().mean_ratio, 1.0, 0.1);
            }
        }
    }
    std::filesystem::remove_all(dir);
}

// With --and-ref the errors are against the references' mean, and the summary prints the
// references' own share: for two references, relMSE(r1, r2) / 4 (two references differ by 2 Var r,
// their mean carries Var r / 2; engine/core/reference_noise.h), which `mvpl compare` measures
// independently. Printed to 3 significant digits: 1% agreement. A second reference of another
// size is an input error.
TEST(ConvergenceCli, AndRefComparesWithTheReferencesMean) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("mvpl_conv2_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string scene = MVPL_ASSETS_DIR "/cornell-box/cbox.gltf";
    const std::string ref1 = (dir / "ref1.exr").string(), ref2 = (dir / "ref2.exr").string();
    const std::string small = (dir / "small.exr").string();
    for (const auto& [path, seed, res] :
         {std::tuple{ref1, 1, "16x16"}, std::tuple{ref2, 2, "16x16"},
          std::tuple{small, 3, "8x8"}}) {
        ASSERT_EQ(test::run_mvpl("reference " + scene + " --res " + res + " --spp 64 --seed " +
                                 std::to_string(seed) + " --quiet -o " + path)
                      .exit_code,
                  0);
    }
    const test::CommandResult compared = test::run_mvpl("compare " + ref1 + " " + ref2);
    ASSERT_EQ(compared.exit_code, 0) << compared.err;
    const double pair = std::stod(compared.out.substr(compared.out.find("relMSE ") + 7));
    const test::CommandResult r = test::run_mvpl(
        "convergence " + scene + " --ref " + ref1 + " --and-ref " + ref2 +
        " --methods pt --budget 0.5 --no-plot --out " + test::shell_quote(dir.string()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const size_t at = r.out.find("relMSE ≈");
    ASSERT_NE(at, std::string::npos) << r.out;
    const double noise = std::stod(r.out.substr(at + std::string("relMSE ≈").size()));
    EXPECT_NEAR(noise, pair / 4.0, 0.01 * pair / 4.0) << r.out;
    EXPECT_NE(r.out.find("relMSE_vs_truth"), std::string::npos) << r.out;
    const test::CommandResult bad = test::run_mvpl(
        "convergence " + scene + " --ref " + ref1 + " --and-ref " + small +
        " --methods pt --budget 0.5 --no-plot --out " + test::shell_quote(dir.string()));
    test::expect_one_line_error(bad, "size differs");
    std::filesystem::remove_all(dir);
}

TEST(ConvergenceCli, UsageErrors) {
    const std::string scene = MVPL_ASSETS_DIR "/cornell-box/cbox.gltf";
    for (const std::string& args :
         {"convergence " + scene, "convergence " + scene + " --ref x.exr --methods pt,foo",
          "convergence " + scene + " --ref x.exr --budget 0",
          "convergence " + scene + " --ref /nonexistent/ref.exr --no-plot --out /tmp"}) {
        const test::CommandResult r = test::run_mvpl(args);
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
        EXPECT_EQ(r.err.rfind("mvpl: error: ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

}  // namespace
}  // namespace mvpl
