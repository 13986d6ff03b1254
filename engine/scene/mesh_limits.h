#pragma once
// The largest mesh a scene loader accepts, for every format: bounds that keep a hostile header or
// index list from asking for an absurd allocation (2^28 triangles of 32-bit indices are 3 GiB)
// before a byte of the mesh is read, while leaving room for every real scene (the largest sample,
// MetalRoughSpheresNoTextures, has about 2^20).
#include <cstdint>

namespace mvpl::scene {

inline constexpr uint64_t kMaxMeshTriangles = uint64_t(1) << 28;
inline constexpr uint64_t kMaxMeshVertices = uint64_t(1) << 28;

}  // namespace mvpl::scene
