// mvpl: the command line. The only place that wires the whole program together.
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "engine/core/error.h"
#include "tools/cli/commands.h"

namespace {

constexpr const char* kUsage =
    "usage: mvpl COMMAND [options]\n"
    "\n"
    "commands:\n"
    "  render SCENE      render with virtual point lights on the GPU\n"
    "  reference SCENE   render with the CPU reference path tracer\n"
    "  compare A B       error of image A against reference B\n"
    "  info              Vulkan devices and their limits\n"
    "  preview SCENE     interactive window, refining while the camera rests\n"
    "  vpls SCENE        where a sampler puts its VPLs, drawn over the scene\n"
    "  bench SCENE       VPL throughput: light paths, shadow and shading passes, memory\n"
    "  convergence SCENE error against run time: path tracer and VPL samplers vs --ref\n"
    "\n"
    "`mvpl COMMAND --help` describes a command's options.\n";

// Errors are one line: embedded newlines (from libraries) are folded.
std::string one_line(std::string text) {
    for (char& c : text) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace mvpl;
    if (argc < 2) {
        std::fputs(kUsage, stderr);
        return 2;
    }
    // Past a file-size limit (ulimit -f) a write should fail and be reported, and the image's
    // temporary removed (atomic_files.h), rather than the process be killed with a partial file.
    std::signal(SIGXFSZ, SIG_IGN);
    const std::string command = argv[1];
    const cli::Args args(argv + 2, argv + argc);
    try {
        if (command == "reference") return cli::run_reference(args);
        if (command == "render") return cli::run_render(args);
        if (command == "compare") return cli::run_compare(args);
        if (command == "info") return cli::run_info(args);
        if (command == "preview") return cli::run_preview(args);
        if (command == "vpls") return cli::run_vpls(args);
        if (command == "bench") return cli::run_bench(args);
        if (command == "convergence") return cli::run_convergence(args);
        if (command == "--help" || command == "-h" || command == "help") {
            std::fputs(kUsage, stdout);
            return 0;
        }
        if (command == "--version") {
            std::puts("mvpl 0.1.0");
            return 0;
        }
        throw UsageError("unknown command '" + command + "' (see mvpl --help)");
    } catch (const InputError& e) {
        std::fprintf(stderr, "mvpl: error: %s\n", one_line(e.what()).c_str());
        return 2;
    } catch (const UsageError& e) {
        std::fprintf(stderr, "mvpl: error: %s\n", one_line(e.what()).c_str());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "mvpl: internal error: %s\n", one_line(e.what()).c_str());
        return 1;
    }
}
