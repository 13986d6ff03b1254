// Imperfect shadow maps (Ritschel et al. 2008; engine/render/ism_pass.h): the layouts that the
// splat and resolve passes (shaders/render/ism_splat.comp, ism_resolve.comp) share with the C++
// that fills them.
#ifndef MVPL_SHADERS_SHARED_ISM_H
#define MVPL_SHADERS_SHARED_ISM_H

#include "prelude.h"

MVPL_SHARED_BEGIN

// The largest face side of an imperfect map: the resolve pass holds a face and its pull-push
// pyramid in shared memory (64² + 32² + … floats ≈ 21 KiB of the 32 KiB lavapipe offers).
const uint kMaxIsmResolution = 64u;

// A scene point, sampled uniformly by area once per scene (ism_points.h).
struct IsmPoint {
    vec3 position;
    float radius;  // of the disc it stands for: √(area / (π · points))
    vec3 normal;   // the triangle's geometric normal (unit)
    float pad;
};

// A VPL whose cube the batch draws as an imperfect map.
struct IsmVpl {
    vec3 position;
    float near_distance;  // points closer than this do not shadow (ShadowPass::near_distance)
    vec3 normal;          // the lit hemisphere's axis (Area and Surface VPLs)
    uint hemisphere;      // 1: only points with normal·(x − position) > 0 are splatted
    uvec4 slot;           // x: the VPL's cube in the batch (layers 6x … 6x + 5)
};

struct IsmPush {
    uint points;       // IsmPoint count
    uint vpls;         // IsmVpl count this dispatch
    uint resolution;   // face side in texels (≤ kMaxIsmResolution)
    uint fill_levels;  // pull-push: the coarsest level a hole may take its depth from
};

#ifdef __cplusplus
MVPL_STD430_MEMBER(IsmPoint, position);
MVPL_STD430_MEMBER(IsmPoint, normal);
MVPL_STD430_MEMBER(IsmVpl, position);
MVPL_STD430_MEMBER(IsmVpl, normal);
MVPL_STD430_MEMBER(IsmVpl, slot);
static_assert(sizeof(IsmPoint) == 32 && sizeof(IsmVpl) == 48);
#endif

MVPL_SHARED_END

#endif
