#include "engine/scene/environment_map.h"

#include <stb_image.h>

#include <cmath>
#include <filesystem>

#include "engine/core/error.h"
#include "engine/core/file_extension.h"
#include "engine/core/image.h"
#include "engine/core/regular_file.h"

namespace mvpl::scene {

namespace {

void check_size(const std::string& path, int64_t width, int64_t height) {
    if (width <= 0 || height <= 0) throw InputError(path, "the image has no texels");
    if (width * height > kMaxEnvironmentTexels) {
        throw InputError(path, "is " + std::to_string(width) + "×" + std::to_string(height) +
                                   ": more than 2^26 texels, too large for memory");
    }
    if (width != 2 * height) {
        throw InputError(path, "is " + std::to_string(width) + "×" + std::to_string(height) +
                                   ": a latitude-longitude map is twice as wide as high");
    }
}

std::shared_ptr<EnvironmentMap> read_hdr(const std::string& path) {
    int width = 0, height = 0, channels = 0;
    if (!stbi_info(path.c_str(), &width, &height, &channels)) {
        const char* reason = stbi_failure_reason();
        throw InputError(path, std::string("cannot decode the image (stb_image: ") +
                                   (reason ? reason : "unknown") + ")");
    }
    check_size(path, width, height);
    float* data = stbi_loadf(path.c_str(), &width, &height, &channels, 3);
    if (!data) {
        const char* reason = stbi_failure_reason();
        throw InputError(path, std::string("cannot decode the image (stb_image: ") +
                                   (reason ? reason : "unknown") + ")");
    }
    auto map = std::make_shared<EnvironmentMap>();
    map->width = width;
    map->height = height;
    map->texels.resize(size_t(width) * size_t(height));
    for (size_t i = 0; i < map->texels.size(); ++i)
        map->texels[i] = Rgb(data[3 * i], data[3 * i + 1], data[3 * i + 2]);
    stbi_image_free(data);
    return map;
}

std::shared_ptr<EnvironmentMap> read_exr_map(const std::string& path) {
    Image image = read_exr(path);
    check_size(path, image.width(), image.height());
    auto map = std::make_shared<EnvironmentMap>();
    map->width = image.width();
    map->height = image.height();
    map->texels = std::move(image.pixels());
    return map;
}

}  // namespace

std::shared_ptr<const EnvironmentMap> load_environment_map(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw InputError(path, "no such environment map");
    require_regular_file(path);
    const std::string ext = lower_extension(path);
    std::shared_ptr<EnvironmentMap> map;
    if (ext == ".hdr") {
        map = read_hdr(path);
    } else if (ext == ".exr") {
        map = read_exr_map(path);
    } else {
        throw InputError(path, "an environment map is .hdr or .exr, not '" + ext + "'");
    }
    for (int y = 0; y < map->height; ++y) {
        for (int x = 0; x < map->width; ++x) {
            const Rgb& t = map->at(x, y);
            for (int c = 0; c < 3; ++c) {
                const char* what = std::isnan(t[c])   ? "NaN"
                                   : std::isinf(t[c]) ? "infinite"
                                   : t[c] < 0.0f      ? "negative"
                                                      : nullptr;
                if (what) {
                    throw InputError(path, "texel (" + std::to_string(x) + ", " +
                                               std::to_string(y) + ") is " + what);
                }
            }
        }
    }
    map->path = path;
    return map;
}

}  // namespace mvpl::scene
