#include "engine/core/atomic_files.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "engine/core/error.h"
#include "engine/core/interrupt.h"

namespace mvpl {
namespace {

// A new empty file beside `target`: ".NAME.XXXXXX" (hidden, and never mistaken for an image).
std::string make_temporary(const std::string& target) {
    const std::filesystem::path p(target);
    const std::filesystem::path dir = p.has_parent_path() ? p.parent_path() : ".";
    std::string name = ".";
    name += p.filename().string();
    name += ".XXXXXX";
    std::string pattern = (dir / name).string();
    const int fd = mkstemp(pattern.data());
    if (fd < 0) throw std::runtime_error(std::strerror(errno));
    // mkstemp makes the file private (0600); the image gets what a plain create would give it.
    const mode_t mask = umask(0);
    umask(mask);
    const int chmod_result = fchmod(fd, 0666 & ~mask);
    close(fd);
    if (chmod_result != 0) {
        const int error = errno;
        std::remove(pattern.c_str());
        throw std::runtime_error(std::strerror(error));
    }
    return pattern;
}

}  // namespace

void write_files_atomically(const std::vector<std::string>& targets,
                            const std::function<void(size_t, const std::string&)>& write) {
    std::vector<std::string> temporaries;
    const auto remove_temporaries = [&] {
        for (const std::string& t : temporaries) {
            std::remove(t.c_str());
            untrack_temporary(t);
        }
    };
    size_t current = 0;
    try {
        for (current = 0; current < targets.size(); ++current) {
            temporaries.push_back(make_temporary(targets[current]));
            track_temporary(temporaries.back());  // a second SIGINT removes it (interrupt.h)
            write(current, temporaries.back());
        }
    } catch (const std::exception& e) {
        remove_temporaries();
        throw InputError(targets[current], std::string("cannot be written: ") + e.what());
    }
    // Every file is complete: only now does any target change.
    for (size_t i = 0; i < targets.size(); ++i) {
        if (std::rename(temporaries[i].c_str(), targets[i].c_str()) != 0) {
            const int error = errno;
            for (size_t j = i; j < targets.size(); ++j)
                std::remove(temporaries[j].c_str());
            for (const std::string& t : temporaries)
                untrack_temporary(t);
            throw InputError(targets[i], std::string("cannot be written: ") + std::strerror(error));
        }
        untrack_temporary(temporaries[i]);
    }
}

void write_bytes(const std::string& path, std::span<const uint8_t> bytes) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) throw std::runtime_error(std::strerror(errno));
    const size_t written = bytes.empty() ? 0 : std::fwrite(bytes.data(), 1, bytes.size(), f);
    int error = written == bytes.size() ? 0 : errno;
    if (std::fflush(f) != 0 && error == 0) error = errno;
    if (std::fclose(f) != 0 && error == 0) error = errno;
    if (written != bytes.size() || error != 0)
        throw std::runtime_error(std::strerror(error != 0 ? error : EIO));
}

}  // namespace mvpl
