// Runs that survive Ctrl-C (engine/core/interrupt.h): SIGINT or SIGTERM during `mvpl render`,
// `mvpl reference` or `mvpl convergence` finishes the chunk in flight, writes what has converged
// and exits 130 (143); a second signal exits at once and leaves no partial file. Outputs rewritten
// as a long render goes (--write-every). And progress as plain lines when stderr is not a terminal
// (engine/core/progress.h).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "engine/core/exr_file.h"
#include "engine/core/image.h"
#include "tests/cli/run_command.h"

namespace {

namespace fs = std::filesystem;
using mvpl::test::shell_quote;

const std::string kScene = std::string(MVPL_ASSETS_DIR) + "/cornell-box/cbox.gltf";

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

class Interrupt : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() /
                ("mvpl_interrupt_" + std::to_string(::getpid()) + "_" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    // `mvpl ARGS` in the background (exec'd by the shell, so that the pid is mvpl's), progress
    // lines every 0.2 s on its stderr file (not a terminal).
    void start(const std::string& args) {
        const std::string cmd = "cd " + shell_quote(m_dir.string()) +
                                " && ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 "
                                "MVPL_PROGRESS_SECONDS=0.2 exec " +
                                shell_quote(MVPL_EXE) + " " + args +
                                " </dev/null >out.txt 2>err.txt";
        m_pid = fork();
        if (m_pid == 0) {
            execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
            _exit(127);
        }
        ASSERT_GT(m_pid, 0);
    }
    // Waits until stderr shows `text` (the job is in its loop) or the process ended.
    bool wait_for_progress(const std::string& text, double seconds = 120.0) {
        const auto until =
            std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (std::chrono::steady_clock::now() < until) {
            if (slurp(m_dir / "err.txt").find(text) != std::string::npos) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        return false;
    }
    // The exit code, or -1 after `seconds` (then the process is killed).
    int wait_exit(double seconds) {
        const auto until =
            std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        int status = 0;
        while (std::chrono::steady_clock::now() < until) {
            if (waitpid(m_pid, &status, WNOHANG) == m_pid)
                return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        kill(m_pid, SIGKILL);
        waitpid(m_pid, &status, 0);
        return -1;
    }
    // Hidden temporaries of the atomic writer (".NAME.XXXXXX") left in the folder.
    int temporaries() const {
        int n = 0;
        for (const auto& e : fs::directory_iterator(m_dir))
            n += e.path().filename().string().rfind(".", 0) == 0;
        return n;
    }
    std::string out() const { return slurp(m_dir / "out.txt"); }
    std::string err() const { return slurp(m_dir / "err.txt"); }

    fs::path m_dir;
    pid_t m_pid = -1;
};

// The image of the chunks before the signal: finite, lit, and the summary says so.
void expect_lit_image(const fs::path& path) {
    ASSERT_TRUE(fs::exists(path));
    const mvpl::Image image = mvpl::read_exr(path.string());
    double sum = 0.0;
    for (const mvpl::Rgb& c : image.pixels()) {
        ASSERT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b));
        sum += c.g;
    }
    EXPECT_GT(sum / double(image.pixels().size()), 0.01);
}

TEST_F(Interrupt, SigintEndsATimeBudgetWithItsImage) {
    start("render " + shell_quote(kScene) + " --res 32x32 --time-budget 600 -o a.exr");
    ASSERT_TRUE(wait_for_progress("render: ")) << err();
    kill(m_pid, SIGINT);
    EXPECT_EQ(wait_exit(60.0), 130) << err();
    expect_lit_image(m_dir / "a.exr");
    EXPECT_NE(out().find("; interrupted"), std::string::npos) << out();
    EXPECT_EQ(temporaries(), 0);
}

TEST_F(Interrupt, SigtermEndsAFixedRenderWithItsImage) {
    start("render " + shell_quote(kScene) + " --res 32x32 --vpls 4294967296 -o a.exr -o a.png");
    ASSERT_TRUE(wait_for_progress("render: ")) << err();
    kill(m_pid, SIGTERM);
    EXPECT_EQ(wait_exit(60.0), 143) << err();
    expect_lit_image(m_dir / "a.exr");
    EXPECT_TRUE(fs::exists(m_dir / "a.png"));
    EXPECT_EQ(temporaries(), 0);
}

TEST_F(Interrupt, ASecondSignalExitsAtOnceWithoutAPartialFile) {
    start("render " + shell_quote(kScene) + " --res 32x32 --time-budget 600 -o a.exr");
    ASSERT_TRUE(wait_for_progress("render: ")) << err();
    kill(m_pid, SIGINT);
    // Delivered apart (two pending SIGINTs merge into one), within the chunk the first lets
    // finish (about half a second under a time budget).
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    kill(m_pid, SIGINT);
    EXPECT_EQ(wait_exit(10.0), 130) << err();
    EXPECT_FALSE(fs::exists(m_dir / "a.exr"));
    EXPECT_EQ(temporaries(), 0);
}

TEST_F(Interrupt, ConvergenceWritesThePointsSoFar) {
    start("convergence " + shell_quote(kScene) + " --ref " +
          shell_quote(std::string(MVPL_ASSETS_DIR) + "/cornell-box/ref-cbox-d6-4096.exr") +
          " --budget 600 --methods mc,metropolis --no-plot --out conv");
    ASSERT_TRUE(wait_for_progress("mc: ")) << err();
    kill(m_pid, SIGINT);
    EXPECT_EQ(wait_exit(60.0), 130) << err();
    const std::string csv = slurp(m_dir / "conv" / "convergence.csv");
    EXPECT_NE(csv.find("mc,"), std::string::npos) << csv;
    EXPECT_EQ(csv.find("metropolis,"), std::string::npos) << csv;  // never started
}

// `mvpl reference --spp N` into `name` in `dir`: the uninterrupted run an interrupted one is
// checked against.
mvpl::Image reference_image(const fs::path& dir, const std::string& args, int spp,
                            const std::string& name) {
    const auto run = mvpl::test::run_mvpl("reference " + args + " --spp " + std::to_string(spp) +
                                          " --quiet -o " + shell_quote((dir / name).string()));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return mvpl::read_exr((dir / name).string());
}

// The reference's samples so far: the EXR says how many (mvpl/spp), holds its AOVs, and is the
// image of an uninterrupted run of that many samples to the bit (each pixel's samples are a
// prefix of its stream, engine/reference/path_film.h), so the tolerance on its mean is zero.
TEST_F(Interrupt, SigintEndsAReferenceWithTheSamplesSoFar) {
    const std::string args = shell_quote(kScene) + " --res 16x16";
    start("reference " + args + " --spp 100000000 -o r.exr -o r.png --aov albedo");
    ASSERT_TRUE(wait_for_progress("reference: ")) << err();
    kill(m_pid, SIGINT);
    EXPECT_EQ(wait_exit(60.0), 130) << err();
    expect_lit_image(m_dir / "r.exr");
    EXPECT_TRUE(fs::exists(m_dir / "r.png"));
    EXPECT_EQ(temporaries(), 0);
    EXPECT_NE(out().find("; interrupted"), std::string::npos) << out();
    EXPECT_EQ(err().find('\r'), std::string::npos);  // plain progress lines, no bar
    const mvpl::ExrContents exr = mvpl::read_exr_file((m_dir / "r.exr").string());
    ASSERT_NE(exr.channel("albedo.R"), nullptr);
    const int spp = std::stoi(exr.attribute("mvpl/spp"));
    ASSERT_GE(spp, 1);
    ASSERT_LT(spp, 100000000);
    EXPECT_NE(out().find(" " + std::to_string(spp) + " spp"), std::string::npos) << out();
    const mvpl::Image got = mvpl::read_exr((m_dir / "r.exr").string());
    const mvpl::Image want = reference_image(m_dir, args, spp, "want.exr");
    ASSERT_EQ(got.pixels().size(), want.pixels().size());
    for (size_t i = 0; i < got.pixels().size(); ++i)
        ASSERT_EQ(got.pixels()[i], want.pixels()[i]) << i;
}

TEST_F(Interrupt, SigtermEndsAReference) {
    start("reference " + shell_quote(kScene) + " --res 16x16 --spp 100000000 -o r.exr");
    ASSERT_TRUE(wait_for_progress("reference: ")) << err();
    kill(m_pid, SIGTERM);
    EXPECT_EQ(wait_exit(60.0), 143) << err();
    expect_lit_image(m_dir / "r.exr");
    EXPECT_EQ(temporaries(), 0);
}

// 1024² at one sample per chunk (a chunk is at least one sample per pixel): the chunk in flight
// lasts seconds, well past the second signal.
TEST_F(Interrupt, ASecondSignalEndsAReferenceWithoutAPartialFile) {
    start("reference " + shell_quote(kScene) + " --res 1024x1024 --spp 1000 -o r.exr");
    ASSERT_TRUE(wait_for_progress("reference: ")) << err();
    kill(m_pid, SIGINT);
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    kill(m_pid, SIGINT);
    EXPECT_EQ(wait_exit(10.0), 130) << err();
    EXPECT_FALSE(fs::exists(m_dir / "r.exr"));
    EXPECT_EQ(temporaries(), 0);
}

// --write-every: the outputs rewritten between chunks (here after every chunk but the last of
// three: 1 536 paths in chunks of 512), and the final image the one without it, to the bit (the
// checkpoints read the estimate and change nothing).
TEST(WriteEvery, RewritesTheOutputsBetweenChunksAndLeavesTheImageAsItWas) {
    const fs::path dir =
        fs::temp_directory_path() / ("mvpl_write_every_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const std::string common = "render " + shell_quote(kScene) + " --res 16x16 --vpls 1536 -o ";
    const auto plain = mvpl::test::run_mvpl_gpu(common + shell_quote((dir / "a.exr").string()));
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    const auto every = mvpl::test::run_mvpl_gpu(common + shell_quote((dir / "b.exr").string()) +
                                                " --write-every 1e-6");
    ASSERT_EQ(every.exit_code, 0) << every.err;
    size_t count = 0;
    for (size_t at = every.out.find("so far"); at != std::string::npos;
         at = every.out.find("so far", at + 1))
        ++count;
    EXPECT_EQ(count, 2u) << every.out;
    EXPECT_EQ(plain.out.find("so far"), std::string::npos) << plain.out;
    const mvpl::Image a = mvpl::read_exr((dir / "a.exr").string());
    const mvpl::Image b = mvpl::read_exr((dir / "b.exr").string());
    ASSERT_EQ(a.pixels().size(), b.pixels().size());
    for (size_t i = 0; i < a.pixels().size(); ++i)
        ASSERT_EQ(a.pixels()[i], b.pixels()[i]) << i;
    mvpl::test::expect_one_line_error(
        mvpl::test::run_mvpl(common + shell_quote((dir / "c.exr").string()) + " --write-every -1"),
        "--write-every");
    fs::remove_all(dir);
}

// The same for the reference: the first chunk is one sample, so 64 make at least two chunks and
// a checkpoint of fewer samples; the final image is the one without checkpoints, to the bit.
TEST(WriteEvery, RewritesTheReferenceBetweenChunksAndLeavesTheImageAsItWas) {
    const fs::path dir =
        fs::temp_directory_path() / ("mvpl_write_every_ref_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const std::string common = "reference " + shell_quote(kScene) + " --res 16x16 --spp 64 -o ";
    const auto plain = mvpl::test::run_mvpl(common + shell_quote((dir / "a.exr").string()));
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    const auto every = mvpl::test::run_mvpl(common + shell_quote((dir / "b.exr").string()) +
                                            " --write-every 1e-6");
    ASSERT_EQ(every.exit_code, 0) << every.err;
    const size_t at = every.out.find("reference: wrote the image of ");
    ASSERT_NE(at, std::string::npos) << every.out;
    EXPECT_LT(std::stoi(every.out.substr(at + 30)), 64) << every.out;
    EXPECT_EQ(plain.out.find("so far"), std::string::npos) << plain.out;
    const mvpl::Image a = mvpl::read_exr((dir / "a.exr").string());
    const mvpl::Image b = mvpl::read_exr((dir / "b.exr").string());
    ASSERT_EQ(a.pixels().size(), b.pixels().size());
    for (size_t i = 0; i < a.pixels().size(); ++i)
        ASSERT_EQ(a.pixels()[i], b.pixels()[i]) << i;
    EXPECT_EQ(mvpl::read_exr_file((dir / "b.exr").string()).attribute("mvpl/spp"), "64");
    mvpl::test::expect_one_line_error(
        mvpl::test::run_mvpl(common + shell_quote((dir / "c.exr").string()) + " --write-every -1"),
        "reference: --write-every");
    fs::remove_all(dir);
}

// Not a terminal: a plain line about every MVPL_PROGRESS_SECONDS; none with --quiet. A 4 s
// budget: under the sanitizers on a loaded machine a 2 s render once printed a single line.
TEST(Progress, PlainLinesWhenStderrIsNotATerminal) {
    const fs::path out = fs::temp_directory_path() / ("mvpl_progress_" + std::to_string(getpid()));
    const auto lines = mvpl::test::run_mvpl_gpu("render " + shell_quote(kScene) +
                                                    " --res 32x32 --time-budget 4 -o " +
                                                    shell_quote((out.string() + ".exr")),
                                                "MVPL_PROGRESS_SECONDS=0.25");
    ASSERT_EQ(lines.exit_code, 0) << lines.err;
    size_t count = 0;
    for (size_t at = lines.err.find("render: "); at != std::string::npos;
         at = lines.err.find("render: ", at + 1))
        ++count;
    EXPECT_GE(count, 3u) << lines.err;                   // 4 s at one line per 0.25 s
    EXPECT_EQ(lines.err.find('\r'), std::string::npos);  // no bar redraws in a log
    const auto quiet = mvpl::test::run_mvpl_gpu("render " + shell_quote(kScene) +
                                                    " --res 32x32 --time-budget 1 --quiet -o " +
                                                    shell_quote((out.string() + ".exr")),
                                                "MVPL_PROGRESS_SECONDS=0.25");
    ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
    EXPECT_EQ(quiet.err, "");
    fs::remove(out.string() + ".exr");
}

// A fixed count whose one chunk is one pool of row-column sampling (2 048 representatives, about
// 2 s at 32² on lavapipe): its batches keep the lines coming while it is shaded, each with the
// VPLs shaded so far, though the bar's paths stand at 0 % until the chunk ends.
TEST(Progress, LinesWhileOneLargePoolIsShaded) {
    const fs::path out = fs::temp_directory_path() / ("mvpl_pool_" + std::to_string(getpid()));
    const auto run = mvpl::test::run_mvpl_gpu(
        "render " + shell_quote(kScene) +
            " --res 32x32 --vpls 8192 --vpl-per-path one --pool 8192 --clusters 2048"
            " --no-compensate -o " +
            shell_quote(out.string() + ".exr"),
        "MVPL_PROGRESS_SECONDS=0.25");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::vector<long> shaded;  // on the lines written before the chunk ended
    std::istringstream lines(run.err);
    for (std::string line; std::getline(lines, line);) {
        const size_t at = line.find(" VPLs shaded");
        if (line.rfind("render: 0% ", 0) != 0 || at == std::string::npos) continue;
        shaded.push_back(std::stol(line.substr(line.rfind(' ', at - 1) + 1)));
    }
    ASSERT_GE(shaded.size(), 2u) << run.err;
    for (size_t i = 1; i < shaded.size(); ++i)
        EXPECT_GE(shaded[i], shaded[i - 1]) << run.err;
    EXPECT_GT(shaded.back(), 0) << run.err;
    EXPECT_LE(shaded.back(), 2048) << run.err;
    fs::remove(out.string() + ".exr");
}

}  // namespace
