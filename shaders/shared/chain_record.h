// A pixel's receiver at the end of its specular chain (engine/light/specular_chain.h), as the
// shading pass reads it from a storage buffer, one per pixel, row by row: written on the CPU by
// engine/render/chain_layer.cpp for each sub-pixel position. The one definition for both sides.
#ifndef MVPL_SHADERS_SHARED_CHAIN_RECORD_H
#define MVPL_SHADERS_SHARED_CHAIN_RECORD_H

#include "prelude.h"

MVPL_SHARED_BEGIN

// ChainRecord::state
const uint kChainNone = 0u;      // not a glossy pixel: shade the G-buffer's receiver
const uint kChainReceiver = 1u;  // shade this record's receiver, weighted by throughput
const uint kChainBlack = 2u;     // a chain that ended without a receiver: no VPL light

struct ChainRecord {
    vec3 position;
    uint state;
    vec3 shading_normal;  // on the side the chain arrived from
    uint max_vpl_length;  // VPLs with a longer light path would exceed max depth
    vec3 geometric_normal;
    float metallic;
    vec3 base_color;
    float roughness;
    vec3 specular_color;
    float specular;
    vec3 wo;  // unit, towards where the chain came from
    float ior;
    vec3 throughput;
    uint closure_type;  // engine/material/closure.h, ClosureType
    // The emitted radiance the chain met after its first vertex, weighted by the throughput to
    // it (ChainedReceiver::chain_emitted), in every state: the emission pass adds it to the
    // pixel's sum (shaders/render/emission_sum.comp), so that the resolve and the preview see it.
    vec3 emitted;
    uint unused;
};

#ifdef __cplusplus
MVPL_STD430_MEMBER(ChainRecord, position);
MVPL_STD430_MEMBER(ChainRecord, shading_normal);
MVPL_STD430_MEMBER(ChainRecord, geometric_normal);
MVPL_STD430_MEMBER(ChainRecord, base_color);
MVPL_STD430_MEMBER(ChainRecord, specular_color);
MVPL_STD430_MEMBER(ChainRecord, wo);
MVPL_STD430_MEMBER(ChainRecord, throughput);
MVPL_STD430_MEMBER(ChainRecord, emitted);
static_assert(sizeof(ChainRecord) == 128);
#endif

MVPL_SHARED_END

#endif
