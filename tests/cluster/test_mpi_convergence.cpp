// `mvpl convergence` under `mpirun -np 2` (issue 17, engine/cluster): every method's curve is
// written by rank 0, the VPL methods' errors are the one-process run's at each amount of work
// (the ranks share Monte Carlo path ranges and Metropolis chains as `mvpl render` does), the path
// tracer's are those of as many samples under other seeds, and a rank that fails makes every rank
// exit with the same code and one error line.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace mvpl {
namespace {

namespace fs = std::filesystem;

const std::string kScene = MVPL_ASSETS_DIR "/cornell-box/cbox.gltf";
const std::string kMvpl = std::string("'") + MVPL_EXE + "'";
const std::string kTwoRanks = std::string(MVPL_MPIRUN) + " -np 2 " + kMvpl;

struct Outcome {
    int exit_code = -1;
    std::string out, err;
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Row {
    uint64_t samples = 0;
    double seconds = 0.0, rel_mse = 0.0;
};

// convergence.csv's rows by method, in file order (time order per method).
std::map<std::string, std::vector<Row>> read_csv(const fs::path& path) {
    std::map<std::string, std::vector<Row>> rows;
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream fields(line);
        std::string method;
        Row r;
        double rmse = 0.0, mean_ratio = 0.0;
        fields >> method >> r.seconds >> r.samples >> r.rel_mse >> rmse >> mean_ratio;
        EXPECT_FALSE(fields.fail()) << line;
        rows[method].push_back(r);
    }
    return rows;
}

// A temporary folder per test with a 16² reference of the Cornell box (1024 spp).
class MpiConvergence : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() /
                ("mvpl_mpiconv_" + std::to_string(::getpid()) + "_" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(m_dir);
        const Outcome ref =
            run(kMvpl + " reference '" + kScene + "' --res 16x16 --spp 1024 --quiet -o ref.exr");
        ASSERT_EQ(ref.exit_code, 0) << ref.err;
    }
    void TearDown() override { fs::remove_all(m_dir); }

    std::string path(const std::string& name) const { return (m_dir / name).string(); }

    // As tests/cluster/test_mpi_render.cpp: `timeout 120` turns a hang into exit 124, and the
    // sanitizer builds' leak checks are off for lavapipe's JIT.
    Outcome run(const std::string& line) const {
        const std::string out = path("out.txt"), err = path("err.txt");
        const std::string cmd = "cd '" + m_dir.string() +
                                "' && ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 "
                                "timeout 120 " +
                                line + " </dev/null >'" + out + "' 2>'" + err + "'";
        const int status = std::system(cmd.c_str());
        Outcome r;
        r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        r.out = slurp(out);
        r.err = slurp(err);
        return r;
    }

    fs::path m_dir;
};

// The bound on |relMSE_a − relMSE_b| when two images of `vpls` VPLs hold the same terms summed in
// another order. Per pixel and channel |x_a − x_b| ≤ δ·x with δ = 2u·depth, u = 2^-24 and the
// depth of the non-negative float sums (Higham §4.2, as in test_mpi_render.cpp): ≤ 32 VPLs a
// batch, then one add per batch (vpls/32 + 1), the ranks' sum and the emission's G-buffers, ≤ 64
// besides the batches. relMSE m = mean d²/(r² + ε), d = x − r; a change of d by at most δx moves
// it by ≤ mean (2|d|δx + δ²x²)/(r² + ε) ≤ 2δ√m·√mean x²/(r²+ε) + δ²·mean x²/(r²+ε) (Cauchy–
// Schwarz), and √mean x²/(r²+ε) ≤ 1 + √m (Minkowski, x = r + d). The CSV prints 6 significant
// digits: another 5·10⁻⁶·m for each of the two values.
double equal_work_tolerance(double m, uint64_t vpls) {
    const double delta = 2.0 * std::ldexp(1.0, -24) * (double(vpls) / 32.0 + 64.0);
    const double x = 1.0 + std::sqrt(m);
    return 2.0 * delta * std::sqrt(m) * x + delta * delta * x * x + 1e-5 * m;
}

TEST_F(MpiConvergence, TwoRanksMatchOneProcess) {
    // Compensation off: its passes run on a thread of their own, so how many a point holds
    // depends on timing, and the equal-work images would differ by them.
    const std::string args = " convergence '" + kScene +
                             "' --ref ref.exr --budget 0.5 --no-plot --quiet --no-compensate"
                             " --out ";
    const Outcome one = run(kMvpl + args + "one");
    ASSERT_EQ(one.exit_code, 0) << one.err;
    const Outcome two = run(kTwoRanks + args + "two");
    ASSERT_EQ(two.exit_code, 0) << two.err;
    const auto a = read_csv(path("one/convergence.csv"));
    const auto b = read_csv(path("two/convergence.csv"));
    for (const std::string method : {"pt", "mc", "metropolis"}) {
        SCOPED_TRACE(method);
        ASSERT_FALSE(b.count(method) == 0 || b.at(method).empty());
        for (const Row& r : b.at(method)) {
            EXPECT_TRUE(std::isfinite(r.rel_mse) && r.rel_mse > 0.0) << r.rel_mse;
            EXPECT_TRUE(std::isfinite(r.seconds) && r.seconds > 0.0) << r.seconds;
        }
        // Every point after the first starts before rank 0's clock reaches the budget; the
        // first, which has no rate to extrapolate from, is always taken.
        const std::vector<Row>& rows = b.at(method);
        for (size_t i = 1; i < rows.size(); ++i)
            EXPECT_LE(rows[i - 1].seconds, 0.5) << "point " << i;
    }
    // The VPL methods: at every amount of work both runs reached, the same error.
    for (const std::string method : {"mc", "metropolis"}) {
        SCOPED_TRACE(method);
        size_t common = 0;
        for (const Row& r : b.at(method)) {
            for (const Row& s : a.at(method)) {
                if (s.samples != r.samples) continue;
                ++common;
                EXPECT_NEAR(r.rel_mse, s.rel_mse, equal_work_tolerance(s.rel_mse, s.samples))
                    << s.samples << " VPLs";
            }
        }
        EXPECT_GE(common, 1u);  // the first point's work is the same in both
    }
    // The path tracer: at the most samples per pixel both reached (both double from 1 or 2 spp),
    // two independent estimates of the same expected relMSE (other seeds; the reference's own
    // noise is shared). Each is a mean of squared errors over 16²·3 terms; counting only 16 of
    // them as effective (the noisiest 2%: the light's edges), their ratio is F(16, 16)-distributed,
    // which exceeds 5 with probability < 10⁻³.
    uint64_t spp = 0;
    double err_a = 0.0, err_b = 0.0;
    for (const Row& r : b.at("pt")) {
        for (const Row& s : a.at("pt")) {
            if (s.samples == r.samples && s.samples > spp) {
                spp = s.samples;
                err_a = s.rel_mse;
                err_b = r.rel_mse;
            }
        }
    }
    ASSERT_GT(spp, 0u);
    EXPECT_LT(err_b, 5.0 * err_a) << spp << " spp";
    EXPECT_LT(err_a, 5.0 * err_b) << spp << " spp";
}

TEST_F(MpiConvergence, RankZeroAloneWritesEveryMethod) {
    // Compensation on (the default): the passes are split by rank and summed with their counts.
    // Each rank picks its device by its local rank.
    const Outcome r = run(kTwoRanks + " convergence '" + kScene +
                          "' --ref ref.exr --budget 0.3 --no-plot --device local-rank");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto rows = read_csv(path("convergence/convergence.csv"));
    for (const std::string method : {"pt", "mc", "metropolis"}) {
        SCOPED_TRACE(method);
        ASSERT_EQ(rows.count(method), 1u);
        for (const Row& p : rows.at(method))
            EXPECT_TRUE(std::isfinite(p.rel_mse) && p.rel_mse > 0.0) << p.rel_mse;
        // One summary line per method: rank 0's.
        const std::string line = "\n" + method + " ";
        const size_t at = ("\n" + r.out).find(line);
        EXPECT_NE(at, std::string::npos) << r.out;
        EXPECT_EQ(at, ("\n" + r.out).rfind(line)) << r.out;
    }
}

// `mpirun -np 1 A : -np 1 B`: one rank names a scene that does not exist. Each rank appends its
// exit code to a file; both exit 2 with one error line between them.
TEST_F(MpiConvergence, FailingRankStopsEveryRank) {
    for (int failing = 0; failing < 2; ++failing) {
        SCOPED_TRACE("failing rank " + std::to_string(failing));
        const std::string codes = path("codes" + std::to_string(failing));
        auto rank = [&](const std::string& scene) {
            return "sh -c \"" + kMvpl + " convergence '" + scene +
                   "' --ref ref.exr --budget 0.2 --no-plot; c=\\$?; echo \\$c >> '" + codes +
                   "'; exit \\$c\"";
        };
        const std::string good = rank(kScene), bad = rank(path("missing.gltf"));
        // Without mpirun's abort on a non-zero exit, which raced with the surviving rank's own
        // exit (test_mpi_render.cpp): every rank has to stop by itself; mpirun then exits 0.
        const Outcome r =
            run(std::string(MVPL_MPIRUN) + " --mca orte_abort_on_non_zero_status 0 -np 1 " +
                (failing == 0 ? bad : good) + " : -np 1 " + (failing == 0 ? good : bad));
        EXPECT_NE(r.exit_code, 124) << "a rank hung";
        EXPECT_EQ(slurp(codes), "2\n2\n");
        size_t lines = 0;
        for (size_t at = r.err.find("mvpl: "); at != std::string::npos;
             at = r.err.find("mvpl: ", at + 1))
            ++lines;
        EXPECT_EQ(lines, 1u) << r.err;
        EXPECT_NE(r.err.find("mvpl: error: "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("missing.gltf"), std::string::npos) << r.err;
    }
}

}  // namespace
}  // namespace mvpl
