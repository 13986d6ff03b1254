// The push constants of the preview's present pass (tools/preview/present_pass.cpp;
// shaders/preview/present.comp), one definition for both (prelude.h).
#ifndef MVPL_SHADERS_SHARED_PRESENT_PUSH_H
#define MVPL_SHADERS_SHARED_PRESENT_PUSH_H

#include "prelude.h"

MVPL_SHARED_BEGIN

struct PresentPush {
    float scale;           // 1 / light paths so far (the stream's scale())
    float exposure_scale;  // 2^exposure
    uint width;            // the display image (the window)
    uint height;
    uint source_width;  // the accumulation: smaller while the camera moves
    uint source_height;
    int hud_x;
    int hud_y;
    uint hud_width;  // 0: no HUD
    uint hud_height;
    uint linear_target;  // 1: the window's format encodes sRGB itself
    // 1: add the CPU estimators' image (the accumulation's size); 2: show it instead (a view of
    // the preview's: albedo, normal, depth)
    uint cpu_image;
};

#ifdef __cplusplus
static_assert(sizeof(int) == 4);
static_assert(sizeof(PresentPush) == 48);  // scalars only: std430 adds no padding
#endif

MVPL_SHARED_END

#endif
