// mvpl: the command line: dispatches to the commands (tools/cli), which parse their options and
// drive the engine (the estimator itself: engine/integrator).
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>

#include "engine/cluster/cluster.h"
#include "engine/core/error.h"
#include "engine/core/interrupt.h"
#include "engine/core/version.h"
#include "tools/cli/command_table.h"

namespace {

// Errors are one line: embedded newlines (from libraries) are folded.
std::string one_line(std::string text) {
    for (char& c : text) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    return text;
}

// Under mpirun, ranks other than 0 print nothing: rank 0 prints progress, results and the one
// error line for all (engine/cluster). MVPL_RANK_OUTPUT=1 keeps every rank's output (debugging).
void silence_other_ranks(const mvpl::cluster::Cluster& ranks) {
    if (ranks.root() || std::getenv("MVPL_RANK_OUTPUT")) return;
    if (!std::freopen("/dev/null", "w", stdout) || !std::freopen("/dev/null", "w", stderr))
        return;  // then they print, which is untidy but harmless
}

int run(const std::string& command, const mvpl::cli::Args& args) {
    using namespace mvpl;
    const cli::Command* found = cli::find_command(command);
    if (found && cluster::world().size() > 1 && !found->over_ranks) {
        // Every rank refuses alike, so no rank waits for another: no MPI_Abort needed.
        const std::string what =
            "under mpirun only `mvpl render`, `mvpl bench` and `mvpl convergence` share their "
            "work over ranks; run '" +
            command + "' as one process";
        throw cluster::RankFailure(what, 2, 0);
    }
    if (found) return found->run(args);
    if (command == "--help" || command == "-h" || command == "help") {
        std::fputs(cli::usage_text().c_str(), stdout);
        return 0;
    }
    if (command == "--version") {
        std::printf("mvpl %s\n", version());
        return 0;
    }
    throw UsageError("unknown command '" + command + "' (see mvpl --help)");
}

}  // namespace

int main(int argc, char** argv) {
    using namespace mvpl;
    if (argc < 2) {
        // As git does: the command list for the newcomer on stdout; the project's one error line
        // and exit code 2 for scripts.
        std::fputs(cli::usage_text().c_str(), stdout);
        std::fputs("mvpl: error: no command given (see mvpl --help)\n", stderr);
        return 2;
    }
    // Past a file-size limit (ulimit -f) a write should fail and be reported, and the image's
    // temporary removed (atomic_files.h), rather than the process be killed with a partial file.
    std::signal(SIGXFSZ, SIG_IGN);
    // MPI_Init when started by mpirun (and MPI_Finalize on return); nothing otherwise.
    const cluster::World world(&argc, &argv);
    cluster::Cluster& ranks = cluster::world();
    const char* launched = std::getenv("OMPI_COMM_WORLD_SIZE");
    if (!cluster::mpi_built() && launched && std::atoi(launched) > 1) {
        // Each rank would render the whole image alone and write the same files.
        std::fputs(
            "mvpl: error: this mvpl was built without MPI (-DMVPL_MPI=OFF): run it without "
            "mpirun, or build it with libopenmpi-dev installed\n",
            stderr);
        return 2;
    }
    silence_other_ranks(ranks);
    const std::string command = argv[1];
    const cli::Args args(argv + 2, argv + argc);
    try {
        const int code = run(command, args);
        // The outputs are written; a shell reports 128 + the signal for an interrupted job.
        return code == 0 && interrupted() ? interrupt_exit_code() : code;
    } catch (const cluster::RankFailure& e) {
        // Every rank has it (an agreement point); the lowest failing rank's message.
        std::fprintf(stderr, "mvpl: %s: %s\n", e.code() == 2 ? "error" : "internal error",
                     one_line(e.what()).c_str());
        return e.code();
    } catch (...) {
        // Past the agreement points (a usage error every rank throws alike, or one rank's
        // failure the others do not know of): on one process the line and its code; across
        // ranks the last resort, MPI_Abort with that code, so that no rank waits forever.
        const std::exception_ptr error = std::current_exception();
        const int code = cluster::exit_code_of(error);
        std::fprintf(stderr, "mvpl: %s: %s\n", code == 2 ? "error" : "internal error",
                     one_line(cluster::message_of(error)).c_str());
        if (ranks.size() > 1) {
            std::fflush(stderr);
            ranks.abort(code);
        }
        return code;
    }
}
