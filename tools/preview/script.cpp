#include "tools/preview/script.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "engine/core/error.h"
#include "engine/sampler/sampler_factory.h"
#include "tools/preview/settings.h"
#include "tools/preview/views.h"

namespace mvpl::preview {
namespace {

size_t value_count(const std::string& action) {
    if (action == "zoom" || action == "camera" || action == "fov") return 1;
    if (action == "fly") return 3;
    if (action == "orbit" || action == "pan" || action == "look" || action == "resize") return 2;
    return size_t(-1);
}

bool known_key(const std::string& key) {
    for (const char* k : {"r", "plus", "minus", "m", "c", "p", "v", "tab", "escape"})
        if (key == k) return true;
    return false;
}

// The numbers after the event; throws with what is wrong (the caller adds file and line).
std::vector<float> read_values(std::istringstream& words, const std::string& what, size_t n) {
    std::vector<float> values;
    for (size_t i = 0; i < n; ++i) {
        float v = 0.0f;
        if (!(words >> v))
            throw std::invalid_argument(what + " needs " + std::to_string(n) + " numbers");
        values.push_back(v);
    }
    return values;
}

void read_setting(std::istringstream& words, ScriptEvent& e) {
    if (!(words >> e.key)) throw std::invalid_argument("set needs a setting's name");
    const SettingSpec* spec = find_setting(e.key);
    if (!spec) throw std::invalid_argument("unknown setting '" + e.key + "'");
    if (spec->values == 0) {
        const auto names = sampler::sampler_names();
        if (!(words >> e.word) || std::find(names.begin(), names.end(), e.word) == names.end())
            throw std::invalid_argument(e.key + " needs mc or metropolis");
        return;
    }
    e.values = read_values(words, e.key, size_t(spec->values));
    for (float v : e.values) {
        const std::string wrong = check_setting_value(*spec, v);
        if (!wrong.empty()) throw std::invalid_argument(wrong);
    }
}

void check_values(const ScriptEvent& e) {
    const std::vector<float>& v = e.values;
    if (e.action == "resize" && (v[0] < 1 || v[1] < 1 || v[0] > 8192 || v[1] > 8192))
        throw std::invalid_argument("resize needs a size in 1..8192");
    if (e.action == "zoom" && !(v[0] > 0.0f))
        throw std::invalid_argument("zoom needs a positive factor");
    if (e.action == "camera" && !(v[0] >= 0.0f && v[0] < 65536.0f && v[0] == float(int(v[0]))))
        throw std::invalid_argument("camera needs a camera's index (0, 1, ...)");
    if (e.action == "fov" && !(v[0] > 0.0f && v[0] < 180.0f))
        throw std::invalid_argument("fov needs degrees in (0, 180)");
}

// The event after the frame number; throws std::invalid_argument saying what is wrong.
ScriptEvent read_event(std::istringstream& words) {
    ScriptEvent e;
    if (!(words >> e.action)) throw std::invalid_argument("missing the event after the frame");
    if (e.action == "key") {
        if (!(words >> e.key) || !known_key(e.key))
            throw std::invalid_argument("key needs one of r, plus, minus, m, c, p, v, tab, escape");
    } else if (e.action == "set") {
        read_setting(words, e);
    } else if (e.action == "view") {
        if (!(words >> e.word) || !is_view_name(e.word))
            throw std::invalid_argument("view needs image, albedo, normal, depth, vpls or error");
    } else if (e.action == "drop") {
        std::getline(words >> std::ws, e.word);
        while (!e.word.empty() && std::isspace(static_cast<unsigned char>(e.word.back())))
            e.word.pop_back();
        if (e.word.empty()) throw std::invalid_argument("drop needs a file");
    } else {
        const size_t n = value_count(e.action);
        if (n == size_t(-1)) {
            throw std::invalid_argument("unknown event '" + e.action +
                                        "' (orbit, pan, zoom, fly, look, resize, key, set, "
                                        "camera, fov, view, drop)");
        }
        e.values = read_values(words, e.action, n);
        check_values(e);
    }
    std::string extra;
    if (words >> extra) throw std::invalid_argument("unexpected '" + extra + "'");
    return e;
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
        uint64_t frame = 0;
        try {
            size_t used = 0;
            const long long f = std::stoll(frame_text, &used);
            if (used != frame_text.size() || f < 0) throw std::invalid_argument("frame");
            frame = uint64_t(f);
        } catch (const std::exception&) {
            throw InputError(path, where + "expected a frame number, got '" + frame_text + "'");
        }
        try {
            ScriptEvent e = read_event(words);
            e.frame = frame;
            events.push_back(std::move(e));
        } catch (const std::invalid_argument& e) {
            throw InputError(path, where + e.what());
        }
    }
    std::stable_sort(events.begin(), events.end(),
                     [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
    return events;
}

}  // namespace mvpl::preview
