// The shadow test of the shading pass against a directional VPL's orthographic map, 1 where the
// VPL sees the receiver. Included by shading_template.glsl after shadow_lookup.glsl (its constants
// and stored_distance) and its bindings (ortho_shadows).

//@if directional
// The same test against a directional VPL's orthographic map (directional_frame.h): w is the
// receiver's distance along the direction of travel from the map's near plane, and a texel is
// extent / resolution wide (in place of d · texel_angle). The first lookup allows a slope bias;
// the junction lookup (thin walls) is visibility()'s with parallel rays, its reach grown by that
// bias, which is what lets a wall's foot pass the first.
// Every surface is drawn into the map, so a receiver whose own texel is empty lies within a texel
// of the outline of everything the map holds (a triangle covers a texel only where it covers the
// texel's centre: Vulkan spec, "Polygon Rasterization"), and what lies over it is in the texels
// beside it. It is shadowed when one of the 3 × 3 holds a surface in front of both the receiver
// and the receiver's own plane at that texel's centre (its own surface there is not in front).
// Without it light entered a closed room of one-sided walls at its edges (docs/results.md,
// "One-sided occluders"). map: the receiver in map coordinates; res: the map's side in texels.
bool occluded_at_outline(uint layer, GpuVpl v, vec3 map, vec3 ng, float texel, float res) {
    const vec3 n = vec3(dot(ng, v.shading_normal), dot(ng, v.wi), dot(ng, v.normal));
    const float n_z = abs(n.z) > 1e-6 ? n.z : 1e-6;
    const ivec2 own = ivec2(floor(map.xy / texel));
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const ivec2 t = own + ivec2(dx, dy);
            if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, ivec2(int(res))))) continue;
            const vec2 stored =
                stored_distance(texelFetch(ortho_shadows, ivec3(t, int(layer)), 0).r, texel);
            const vec2 offset = (vec2(t) + 0.5) * texel - map.xy;
            const float plane = min(map.z, map.z - dot(n.xy, offset) / n_z);
            if (stored.x < plane - (kConstantBias * map.z + kFootprintBias * texel + stored.y))
                return true;
        }
    }
    return false;
}

// occluder_plane_passes_behind (shadow_lookup.glsl) along the map's parallel rays, in its
// (u, v, w) coordinates, where shadow.frag took the plane: the plane through the texel's centre c
// at the stored w meets the ray through the receiver's (u, v) at w_o = stored − n_uv·(uv − c)/n_w.
// A texel is found as the sampler's nearest filtering finds it (clamped to the map).
bool ortho_plane_passes_behind(vec2 texel_value, vec3 map, float texel, float res,
                               float allowance) {
    const float stored = abs(texel_value.x);
    if (texel_value.y == kNoOccluderPlane || stored >= kShadowNoOccluder) return false;
    const vec3 n = occluder_plane_normal(texel_value.y);
    if (abs(n.z) < kMinPlaneCos * length(n)) return false;
    const vec2 centre = (clamp(floor(map.xy / texel), vec2(0.0), vec2(res - 1.0)) + 0.5) * texel;
    return stored - dot(n.xy, map.xy - centre) / n.z > map.z + allowance;
}

float directional_visibility(uint layer, GpuVpl v, vec3 p, vec3 ng) {
    const vec3 map = vec3(dot(p, v.shading_normal), dot(p, v.wi), dot(p, v.normal)) - v.position;
    const float res = float(textureSize(ortho_shadows, 0).x);
    const float texel = v.map_extent / res;
    const vec2 texel_value =
        textureLod(ortho_shadows, vec3(map.xy / v.map_extent, float(layer)), 0.0).rg;
    const vec2 stored = stored_distance(texel_value.x, texel);
    const float cos_r = abs(dot(ng, v.normal));
    const float tan_r = min(sqrt(max(0.0, 1.0 - cos_r * cos_r)) / max(cos_r, 1e-6), kMaxSlope);
    const float bias = kConstantBias * map.z + kSlopeBias * texel * tan_r + stored.y;
    bool lit = stored.x >= map.z - bias;
    if (!lit)
        lit = ortho_plane_passes_behind(texel_value, map, texel, res,
                                        kConstantBias * map.z + stored.y);
    if (stored.x >= kShadowNoOccluder && occluded_at_outline(layer, v, map, ng, texel, res))
        lit = false;
//@if thin_walls
    const float cos_g = dot(ng, v.normal);
    const vec3 towards_light = cos_g <= 0.0 ? ng : -ng;
    const float sin_g = sqrt(max(0.0, 1.0 - cos_g * cos_g));
    const vec3 q = p + towards_light * (kNormalOffset * texel * sin_g);
    const vec3 moved = vec3(dot(q, v.shading_normal), dot(q, v.wi), dot(q, v.normal)) - v.position;
    const vec2 moved_value =
        textureLod(ortho_shadows, vec3(moved.xy / v.map_extent, float(layer)), 0.0).rg;
    const vec2 near = stored_distance(moved_value.x, texel);
    const float in_front = moved.z - near.x;
    if (in_front > kConstantBias * moved.z + near.y &&
        in_front < (kJunctionReach + kSlopeBias * tan_r) * texel &&
        !ortho_plane_passes_behind(moved_value, moved, texel, res,
                                   kConstantBias * moved.z + near.y))
        lit = false;
//@endif
    return lit ? 1.0 : 0.0;
}
//@endif
