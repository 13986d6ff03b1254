#pragma once
// `mvpl preview --script FILE`: input events at given frames, so that tests and measurements
// can drive the window without a user. One event a line, `#` starts a comment:
//
//   FRAME orbit YAW PITCH     degrees (as a left drag)
//   FRAME pan RIGHT UP        fractions of the view height (as a middle drag)
//   FRAME zoom FACTOR         distance to the target × FACTOR (as the wheel)
//   FRAME fly FWD RIGHT UP    scene diagonals (as WASD)
//   FRAME look YAW PITCH      degrees about the eye (as a right drag)
//   FRAME resize W H          window size in screen coordinates
//   FRAME key NAME            r, plus, minus, m, c, p, v, tab or escape (as the key)
//   FRAME set NAME VALUE…     a setting of settings.h (as the settings panel)
//   FRAME camera N            the file's camera N (as the panel's camera list)
//   FRAME fov DEGREES         the vertical field of view
//   FRAME view NAME           image, albedo, normal, depth or vpls (as V)
//   FRAME drop FILE           a scene or environment map dropped on the window
//
// FRAME is the index of the frame (from 0) at whose start the event happens; events of one frame
// run in file order. Frames, not seconds, so that a run is the same on a fast and a slow machine.
#include <cstdint>
#include <string>
#include <vector>

namespace mvpl::preview {

struct ScriptEvent {
    uint64_t frame = 0;
    std::string action;  // orbit, pan, zoom, fly, look, resize, key, set, camera, fov, view, drop
    std::vector<float> values;
    std::string key;   // for `key`; the setting's name for `set`
    std::string word;  // the sampler of `set sampler`, the view of `view`, the file of `drop`
};

// Sorted by frame, file order within a frame. Throws InputError naming file:line.
std::vector<ScriptEvent> load_script(const std::string& path);

}  // namespace mvpl::preview
