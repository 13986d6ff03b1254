// What a shadow texel holds: the shadow pass's cubes and orthographic maps
// (engine/render/shadow_pass.h), the imperfect maps' resolve (shaders/render/ism_resolve.comp) and
// the shading pass's tests (shaders/render/shading_template.glsl) read the same value.
#ifndef MVPL_SHADERS_SHARED_SHADOW_MAP_H
#define MVPL_SHADERS_SHARED_SHADOW_MAP_H

#include "prelude.h"

MVPL_SHARED_BEGIN

// The distance a shadow texel holds where no surface was rendered.
const float kShadowNoOccluder = 3.0e38f;

MVPL_SHARED_END

#endif
