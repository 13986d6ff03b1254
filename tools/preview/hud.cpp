#include "tools/preview/hud.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace mvpl::preview {
namespace {
constexpr int kMargin = 4;  // pixels around the text
}

struct HudFont::Impl {
    ImFontAtlas atlas;
    ImFont* font = nullptr;
    unsigned char* pixels = nullptr;  // alpha8, owned by the atlas
    int atlas_width = 0;
    int atlas_height = 0;
};

HudFont::HudFont() : m_impl(std::make_unique<Impl>()) {
    Impl& m = *m_impl;
    m.font = m.atlas.AddFontDefault();
    m.atlas.GetTexDataAsAlpha8(&m.pixels, &m.atlas_width, &m.atlas_height);
}

HudFont::~HudFont() = default;

HudBitmap HudFont::render(const std::vector<std::string>& lines, int32_t x, int32_t y,
                          uint32_t max_width) const {
    const Impl& m = *m_impl;
    const int line_height = int(std::ceil(m.font->FontSize));
    int text_width = 0;
    for (const std::string& line : lines) {
        float w = 0.0f;
        for (char c : line)
            if (const ImFontGlyph* g = m.font->FindGlyph(ImWchar(uint8_t(c)))) w += g->AdvanceX;
        text_width = std::max(text_width, int(std::ceil(w)));
    }
    HudBitmap hud;
    hud.x = x;
    hud.y = y;
    hud.width = std::min(uint32_t(text_width + 2 * kMargin), max_width);
    hud.height = uint32_t(int(lines.size()) * line_height + 2 * kMargin);
    if (lines.empty() || hud.width == 0) return HudBitmap{};
    hud.rgba.assign(size_t(hud.width) * hud.height * 4, 0);
    for (size_t l = 0; l < lines.size(); ++l) {
        float pen = float(kMargin);
        const int top = kMargin + int(l) * line_height;
        for (char c : lines[l]) {
            const ImFontGlyph* g = m.font->FindGlyph(ImWchar(uint8_t(c)));
            if (!g) continue;
            const int gw = int(std::lround(g->X1 - g->X0));
            const int gh = int(std::lround(g->Y1 - g->Y0));
            const int u0 = int(std::lround(g->U0 * float(m.atlas_width)));
            const int v0 = int(std::lround(g->V0 * float(m.atlas_height)));
            const int dx = int(std::lround(pen + g->X0));
            const int dy = top + int(std::lround(g->Y0));
            for (int j = 0; j < gh; ++j) {
                for (int i = 0; i < gw; ++i) {
                    const int px = dx + i, py = dy + j;
                    if (px < 0 || py < 0 || px >= int(hud.width) || py >= int(hud.height)) continue;
                    const uint8_t a =
                        m.pixels[size_t(v0 + j) * size_t(m.atlas_width) + size_t(u0 + i)];
                    uint8_t* out = &hud.rgba[(size_t(py) * hud.width + size_t(px)) * 4];
                    out[0] = out[1] = out[2] = 255;
                    out[3] = std::max(out[3], a);
                }
            }
            pen += g->AdvanceX;
        }
    }
    return hud;
}

}  // namespace mvpl::preview
