#include "tools/preview/script.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "engine/core/error.h"

namespace mvpl::preview {
namespace {

size_t value_count(const std::string& action) {
    if (action == "zoom") return 1;
    if (action == "fly") return 3;
    if (action == "orbit" || action == "pan" || action == "look" || action == "resize") return 2;
    return size_t(-1);
}

bool known_key(const std::string& key) {
    for (const char* k : {"r", "plus", "minus", "m", "c", "p", "escape"})
        if (key == k) return true;
    return false;
}

}  // namespace

std::vector<ScriptEvent> load_script(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError(path, "cannot open the script");
    std::vector<ScriptEvent> events;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const size_t hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        std::istringstream words(line);
        std::string frame_text;
        if (!(words >> frame_text)) continue;  // blank or comment
        const std::string where = "line " + std::to_string(number) + ": ";
        ScriptEvent e;
        try {
            size_t used = 0;
            const long long frame = std::stoll(frame_text, &used);
            if (used != frame_text.size() || frame < 0) throw std::invalid_argument("frame");
            e.frame = uint64_t(frame);
        } catch (const std::exception&) {
            throw InputError(path, where + "expected a frame number, got '" + frame_text + "'");
        }
        if (!(words >> e.action))
            throw InputError(path, where + "missing the event after the frame");
        if (e.action == "key") {
            if (!(words >> e.key) || !known_key(e.key))
                throw InputError(path, where + "key needs one of r, plus, minus, m, c, p, escape");
        } else {
            const size_t n = value_count(e.action);
            if (n == size_t(-1)) {
                throw InputError(path, where + "unknown event '" + e.action +
                                           "' (orbit, pan, zoom, fly, look, resize, key)");
            }
            for (size_t i = 0; i < n; ++i) {
                float v = 0.0f;
                if (!(words >> v))
                    throw InputError(path,
                                     where + e.action + " needs " + std::to_string(n) + " numbers");
                e.values.push_back(v);
            }
            if (e.action == "resize" &&
                (e.values[0] < 1 || e.values[1] < 1 || e.values[0] > 8192 || e.values[1] > 8192)) {
                throw InputError(path, where + "resize needs a size in 1..8192");
            }
            if (e.action == "zoom" && !(e.values[0] > 0.0f))
                throw InputError(path, where + "zoom needs a positive factor");
        }
        std::string extra;
        if (words >> extra) throw InputError(path, where + "unexpected '" + extra + "'");
        events.push_back(std::move(e));
    }
    std::stable_sort(events.begin(), events.end(),
                     [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
    return events;
}

}  // namespace mvpl::preview
