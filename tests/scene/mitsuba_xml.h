#pragma once
// Scenes for the Mitsuba loader's tests, written as XML files into a temporary folder.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace mvpl::scene::testing {

// One folder per process: ctest runs each test as its own process, in parallel, and two tests
// writing the same file name into one folder would read each other's scenes.
inline std::filesystem::path mitsuba_temp_dir() {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("mvpl_mitsuba_loader_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

// `text` as the file `name` in the temporary folder; its path.
inline std::filesystem::path write_file(const std::string& name, const std::string& text) {
    const std::filesystem::path p = mitsuba_temp_dir() / name;
    std::ofstream(p) << text;
    return p;
}

inline std::string scene_xml(const std::string& body, const std::string& version = "3.0.0") {
    return "<scene version=\"" + version + "\">\n" + body + "\n</scene>\n";
}

}  // namespace mvpl::scene::testing
