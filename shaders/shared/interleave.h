// Interleaved sampling (Keller & Heidrich 2001, "Interleaved Sampling"): in each K×K block of
// pixels, the pixel of class c = (x mod K) + K · (y mod K) shades only the VPLs of a batch whose
// index since begin() is c mod K², times K²; a geometry-aware filter then averages each pixel
// over the K×K neighbourhood of pixels on the same surface, so that where the whole
// neighbourhood is accepted every VPL is counted once. The GPU filter
// (shaders/render/interleave_filter.comp) and the CPU oracle's
// (engine/reference/interleaved_gather.cpp) read these constants, so that both accept the same
// neighbours.
//
// The window: for odd K the K×K pixels centred on the pixel; for even K the (K+1)×(K+1) ones,
// the outer rows and columns weighted ½ (the two share their class, so that every class weighs
// 1 in all and the window stays centred: an even K×K window would shift the image by half a
// pixel). Near the image's border the window's centre moves inwards until the window fits.
//
// Same surface: both covered by the same material, geometric (winding) normals within
// acos(kInterleaveMinCos) = 25.8°, and the neighbour within kInterleavePlaneSlope (5.7°) of the
// pixel's tangent plane as seen from it — exact on a plane (every neighbour is accepted), and it
// rejects the other side of a crease or a depth step. A smooth curved surface keeps its
// neighbours as long as a K-pixel footprint turns its normal by less than those angles. And the
// closure's base colour (textures) within kInterleaveAlbedo relative per channel: the shares are
// demodulated by the neighbour's base colour and modulated by the pixel's own, so that the filter
// averages lighting, not texture detail (a textured box lost its texels' contrast otherwise:
// tests/cli/test_sample_models, BoxTextured).
//
// Chains (specular chains, shared/chain_record.h): a chained pixel (kChainReceiver) is lit at its
// chain's rough end, so its neighbours are the chained pixels whose rough ends pass the same
// tests on the records: the normal and plane tests on their positions and geometric normals (the
// plane test is relative to the distance, so it needs no scale of its own), in place of the
// material the same closure type, base colour within kInterleaveAlbedo and the same VPL
// path-length limit, and where the end is not Lambertian (whose BSDF is base / π whatever the
// directions) every other closure parameter within kInterleaveAlbedo relative and the
// directions towards the chains (wo) within acos(kInterleaveMinCos) (the G-buffer's neighbours
// share the camera's direction to within a few pixel angles; two chains' may differ by any). A
// chained pixel never takes an unchained or black (kChainBlack) neighbour, nor an unchained pixel
// a chained or black one; a black pixel gets no VPL light. The shading pass stores the unweighted
// sums (tagged with 1 + the chain's state in alpha), and the filter multiplies the mean by the
// pixel's own throughput: the chain's weight is a per-pixel factor of the estimate (shade at the
// rough end, then weight), so it stays outside the average, and a neighbour's weight — a
// different path's — never enters a pixel. The oracle (reference/interleaved_gather.cpp) does
// the same with the same chains.
#ifndef MVPL_SHADERS_SHARED_INTERLEAVE_H
#define MVPL_SHADERS_SHARED_INTERLEAVE_H

#include "prelude.h"

MVPL_SHARED_BEGIN

const float kInterleaveMinCos = 0.9;
const float kInterleavePlaneSlope = 0.1;
const float kInterleaveAlbedo = 0.1;
const float kInterleaveMinAlbedo = 1e-3;  // the demodulation's floor
const uint kMaxInterleave = 8u;

MVPL_SHARED_END

#endif
