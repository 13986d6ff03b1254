#pragma once
// The preview's HUD as a text overlay: lines of text rasterised on the CPU with Dear ImGui's
// built-in font (ProggyClean, from Debian's libimgui-dev; only its font atlas is used, no ImGui
// backend), into an RGBA8 image with coverage in alpha that the present pass blends on top.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mvpl::preview {

struct HudBitmap {
    uint32_t width = 0;
    uint32_t height = 0;
    int32_t x = 0;  // top-left corner in the window
    int32_t y = 0;
    std::vector<uint8_t> rgba;  // rows top first
};

class HudFont {
public:
    HudFont();
    ~HudFont();
    HudFont(const HudFont&) = delete;
    HudFont& operator=(const HudFont&) = delete;

    // White text, one line per entry, with a small margin, at (x, y); clipped to max_width.
    HudBitmap render(const std::vector<std::string>& lines, int32_t x, int32_t y,
                     uint32_t max_width) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace mvpl::preview
