#pragma once
// `mvpl preview` in a virtual X server for the window's tests: the server, a scratch folder, and
// the bound within which two estimates of the same VPLs agree.
#include <filesystem>
#include <string>

#include "engine/core/image.h"
#include "tests/cli/run_command.h"

namespace mvpl::test {

// A folder of this test process's own.
std::filesystem::path preview_temp_dir();
bool have_xvfb();
// xvfb-run with a 24-bit screen, on a server number of this process's own.
std::string xvfb();
// `mvpl preview ARGS` under xvfb-run (and `env -C FOLDER` when given: its working directory).
CommandResult run_preview(const std::string& args, const std::string& folder = {});
// The image's pixels whose radiance differs from the other's by more than the summation bound of
// two estimates of the same VPLs in other groups (test_preview.cpp,
// RestingRadianceEqualsTheRenderWithCompensation: 1e-5 relative), over all channels; `lit` gets
// the channels of b above 0 (not two black images).
size_t channels_differing(const Image& a, const Image& b, size_t* lit = nullptr);

}  // namespace mvpl::test
