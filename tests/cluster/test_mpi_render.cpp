// `mvpl render` and `mvpl bench` under `mpirun -np 2` (issue 17, engine/cluster): the ranks' image
// equals the one-process image with the same seed (with row-column sampling too, issue 36), a time
// budget ends every rank, the bench counts the job's VPLs and representatives, and a rank that
// fails makes every rank exit with the same code and one error line.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/core/image.h"

namespace mvpl {
namespace {

namespace fs = std::filesystem;

const std::string kScene = MVPL_ASSETS_DIR "/cornell-box/cbox.gltf";

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

// A temporary folder per test, removed at the end.
class MpiRender : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() /
                ("mvpl_mpi_" + std::to_string(::getpid()) + "_" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    std::string path(const std::string& name) const { return (m_dir / name).string(); }

    // `mvpl` + one_process and two ranks' `mvpl` + ranks (one_process when empty) render the same
    // image (expect_same_image).
    void expect_ranks_equal_one_process(const std::string& one_process,
                                        std::string ranks = {}) const;

    // Runs a shell command line in the folder. `timeout 120`: a hang fails the test (exit 124)
    // instead of blocking the suite. Sanitizer builds: lavapipe's JIT leaks what LeakSanitizer
    // cannot suppress (tests/cli/run_command.h), so leak checks are off for these renders.
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

const std::string kMvpl = std::string("'") + MVPL_EXE + "'";
const std::string kTwoRanks = std::string(MVPL_MPIRUN) + " -np 2 " + kMvpl;

// Per pixel and channel |a − b| ≤ 1e-5 · max(|a|, |b|). Both images hold the same terms: the same
// VPLs (the ranks trace disjoint ranges of the one-process path indices, or run its chains) at
// the same sub-pixel positions, the same compensation passes, the same G-buffers' emission; only
// the order of the float sums differs. Every term is non-negative, so a sum's relative rounding
// error is at most its depth times u = 2^-24 (Higham, "Accuracy and Stability of Numerical
// Algorithms", §4.2): the GPU adds ≤ 32 VPLs per batch and then each batch's sum, depth ≤ 32 +
// 24 batches here (≈ 740 VPLs) + 1 for the ranks' sum, ≤ 3.4·10⁻⁶ each, 6.8·10⁻⁶ between the two;
// the emission's 24 G-buffers ≤ 2·24·u = 2.9·10⁻⁶; the compensation passes are summed in double.
void expect_same_image(const std::string& a_path, const std::string& b_path) {
    const Image a = read_exr(a_path), b = read_exr(b_path);
    ASSERT_EQ(a.width(), b.width());
    ASSERT_EQ(a.height(), b.height());
    size_t lit = 0, bad = 0;
    double worst = 0.0;
    for (size_t i = 0; i < a.pixels().size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double x = a.pixels()[i][c], y = b.pixels()[i][c];
            const double bound = 1e-5 * std::max(std::abs(x), std::abs(y));
            lit += x > 0.0 ? 1 : 0;
            if (std::abs(x - y) > bound) ++bad;
            if (bound > 0.0) worst = std::max(worst, std::abs(x - y) / bound * 1e-5);
        }
    }
    EXPECT_GT(lit, a.pixels().size());  // a lit image, not two black ones
    EXPECT_EQ(bad, 0u) << "worst relative difference " << worst;
}

void MpiRender::expect_ranks_equal_one_process(const std::string& one_process,
                                               std::string ranks) const {
    if (ranks.empty()) ranks = one_process;
    const Outcome one = run(kMvpl + one_process + " -o one.exr");
    ASSERT_EQ(one.exit_code, 0) << one.err;
    const Outcome two = run(kTwoRanks + ranks + " -o two.exr");
    ASSERT_EQ(two.exit_code, 0) << two.err;
    expect_same_image(path("two.exr"), path("one.exr"));
}

TEST_F(MpiRender, MonteCarloEqualsOneProcess) {
    const std::string args = " render '" + kScene + "' --vpls 256 --res 48x48 --seed 7 --quiet";
    expect_ranks_equal_one_process(args);
}

TEST_F(MpiRender, MetropolisEqualsOneProcess) {
    // The ranks hold the whole bootstrap and run its chains (c mod 2 = rank); b's sums are the
    // same numbers added in another order (double), far below any acceptance decision's margin.
    const std::string args = " render '" + kScene +
                             "' --sampler metropolis --vpls 512 --chains 64 --bootstrap 4096 "
                             "--res 48x48 --seed 7 --quiet";
    expect_ranks_equal_one_process(args);
}

// Row-column sampling (--pool, engine/manylights): each rank cuts its own share of the VPLs into
// pools, numbered in the one-process order. With one VPL a path, each rank's share of the 256
// paths is 128 VPLs, four whole pools of 32: the pools, and so their rows, clusters and
// representatives, are one process's, shaded at the one-process positions, paced and resolved
// by every rank's representatives; the image is the one-process image to rounding (fewer terms
// than above: 64 representatives).
TEST_F(MpiRender, RowColumnEqualsOneProcess) {
    const std::string args = " render '" + kScene +
                             "' --vpls 256 --vpl-per-path one --pool 32 --clusters 8 --rows 16 "
                             "--res 48x48 --seed 7 --quiet";
    expect_ranks_equal_one_process(args);
}

// The same with the reduced matrix on each rank's GPU renderer.
TEST_F(MpiRender, RowColumnWithTheGpuMatrixEqualsOneProcess) {
    const std::string args = " render '" + kScene +
                             "' --vpls 256 --vpl-per-path one --pool 32 --clusters 8 --rows 16 "
                             "--matrix gpu --res 48x48 --seed 7 --quiet";
    expect_ranks_equal_one_process(args);
}

// Shares that are not whole pools (all the VPLs of each path: each rank's last pool is short)
// with a cluster per VPL: every VPL its own representative, numbered across the ranks' pools
// in the one-process order, so the image is the one-process image without row-column sampling.
TEST_F(MpiRender, RowColumnWithAClusterPerVplEqualsEveryVpl) {
    const std::string args = " render '" + kScene + "' --vpls 256 --res 48x48 --seed 7 --quiet";
    expect_ranks_equal_one_process(args, args + " --pool 100 --clusters 100");
}

TEST_F(MpiRender, TimeBudgetEndsEveryRank) {
    // Rank 0's clock decides for both; each rank picks its device by its local rank.
    const Outcome r = run(kTwoRanks + " render '" + kScene +
                          "' --time-budget 1 --res 32x32 --device local-rank -o budget.exr");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(path("budget.exr")));
    // Rank 0 alone prints: one summary line.
    const size_t summary = r.out.find("VPL/s");
    EXPECT_NE(summary, std::string::npos) << r.out;
    EXPECT_EQ(summary, r.out.rfind("VPL/s")) << r.out;
    // The ranks shared the work and summed their images (not each the whole render alone).
    EXPECT_NE(r.out.find("; 2 ranks, images summed in"), std::string::npos) << r.out;
}

// The JSON's value of `key` (a number), or "" when it is missing.
std::string json_number(const std::string& json, const std::string& key) {
    const size_t at = json.find("\"" + key + "\": ");
    if (at == std::string::npos) return "";
    const size_t from = at + key.size() + 4;
    return json.substr(from, json.find_first_of(",\n}", from) - from);
}

TEST_F(MpiRender, BenchSharesTheLightPaths) {
    // The job's VPLs are the one-process bench's (the same paths, traced half by each rank), and
    // rank 0 alone prints the table.
    const std::string args = " bench '" + kScene + "' --res 32x32 --vpls 128 --repeat 1 --json ";
    const Outcome one = run(kMvpl + args + "one.json");
    ASSERT_EQ(one.exit_code, 0) << one.err;
    const Outcome two = run(kTwoRanks + args + "two.json");
    ASSERT_EQ(two.exit_code, 0) << two.err;
    const std::string a = slurp(path("one.json")), b = slurp(path("two.json"));
    EXPECT_EQ(json_number(a, "ranks"), "1") << a;
    EXPECT_EQ(json_number(b, "ranks"), "2") << b;
    EXPECT_NE(json_number(a, "vpls"), "");
    EXPECT_EQ(json_number(b, "vpls"), json_number(a, "vpls"));
    EXPECT_EQ(two.out.find("bench: "), two.out.rfind("bench: ")) << two.out;
    EXPECT_NE(two.out.find("2 MPI ranks"), std::string::npos) << two.out;
}

TEST_F(MpiRender, BenchCountsEveryRanksRepresentatives) {
    // A cluster per VPL: every VPL is shaded as its own representative, on one rank or the other,
    // so the job's representatives (summed over the ranks) are its VPLs.
    const Outcome r = run(kTwoRanks + " bench '" + kScene +
                          "' --res 32x32 --vpls 128 --repeat 1 --pool 100 --clusters 100 "
                          "--rows 16 --json rc.json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string json = slurp(path("rc.json"));
    EXPECT_NE(json_number(json, "vpls"), "") << json;
    EXPECT_EQ(json_number(json, "representatives"), json_number(json, "vpls")) << json;
}

TEST_F(MpiRender, OtherCommandsAreRefusedAlike) {
    const Outcome r = run(kTwoRanks + " vpls '" + kScene + "' -o v.png");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("mvpl: error: under mpirun only"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("mvpl: "), r.err.rfind("mvpl: ")) << r.err;
}

// `mpirun -np 1 A : -np 1 B` starts rank 0 with A and rank 1 with B: one of them names a scene
// that does not exist. Each rank appends its exit code to a file.
// By default mpirun kills the other ranks as soon as one exits non-zero, which raced with the
// surviving rank's own exit: its code was written or not (one CI run in a few). Without that,
// every rank has to stop by itself, which is the property tested; mpirun then exits 0.
const std::string kKeepRanks = " --mca orte_abort_on_non_zero_status 0";

void expect_all_exit_2(const Outcome& r, const std::string& codes_file) {
    EXPECT_NE(r.exit_code, 124) << "a rank hung";
    const std::string codes = slurp(codes_file);
    EXPECT_EQ(codes, "2\n2\n") << codes;
    // One line from mvpl (mpirun adds its own report of the exit code).
    size_t lines = 0;
    for (size_t at = r.err.find("mvpl: "); at != std::string::npos;
         at = r.err.find("mvpl: ", at + 1))
        ++lines;
    EXPECT_EQ(lines, 1u) << r.err;
    EXPECT_NE(r.err.find("mvpl: error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("missing.gltf"), std::string::npos) << r.err;
}

std::string rank_command(const std::string& scene, const std::string& codes_file) {
    return "sh -c \"" + kMvpl + " render '" + scene +
           "' --vpls 64 --res 32x32 -o x.exr; c=\\$?; echo \\$c >> '" + codes_file +
           "'; exit \\$c\"";
}

TEST_F(MpiRender, FailingRankStopsEveryRank) {
    for (int failing = 0; failing < 2; ++failing) {
        const std::string codes = path("codes" + std::to_string(failing));
        const std::string good = rank_command(kScene, codes);
        const std::string bad = rank_command(path("missing.gltf"), codes);
        const Outcome r =
            run(std::string(MVPL_MPIRUN) + kKeepRanks + " -np 1 " + (failing == 0 ? bad : good) +
                " : -np 1 " + (failing == 0 ? good : bad));
        SCOPED_TRACE("failing rank " + std::to_string(failing));
        expect_all_exit_2(r, codes);
    }
}

}  // namespace
}  // namespace mvpl
