#pragma once
// Dynamic rendering (Vulkan 1.3, no render pass objects) into layers of mvpl Images, for the
// draws of graphics_pipeline.h between begin_rendering and end_rendering. Vulkan-free to include.
#include <array>
#include <cstdint>
#include <span>

namespace mvpl::gpu {

class CommandList;
class Image;

// One layer of an image as an attachment, cleared at the start of rendering.
struct ColorTarget {
    const Image* image = nullptr;
    uint32_t layer = 0;
    std::array<float, 4> clear{0.0f, 0.0f, 0.0f, 0.0f};
};
struct DepthTarget {
    const Image* image = nullptr;
    uint32_t layer = 0;
    float clear = 0.0f;  // reversed depth: 0 is infinitely far
};

// A rectangle of texels: the render area of a pass that fills only part of its targets.
struct RenderArea {
    uint32_t x = 0;
    uint32_t y = 0;
    uint32_t width = 0;
    uint32_t height = 0;
};

// Begins dynamic rendering over the full extent of the targets (all of the same size) and sets
// the viewport to it. depth may be nullptr. With an area, only it is cleared and drawn (render
// area and scissor; texels outside keep what they held); the viewport stays the full extent.
void begin_rendering(CommandList& cmd, std::span<const ColorTarget> colors,
                     const DepthTarget* depth, const RenderArea* area = nullptr);
void end_rendering(CommandList& cmd);

}  // namespace mvpl::gpu
