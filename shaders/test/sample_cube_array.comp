#version 460
// Test shader: samples the centre of every face of every cube in a cube-map array, to check the
// face order (+X −X +Y −Y +Z −Z) and the layer = 6·cube + face mapping that the shadow pass uses.
// One work group per cube, one invocation per face.
layout(local_size_x = 6) in;

layout(set = 0, binding = 0) uniform samplerCubeArray cubes;
layout(std430, set = 0, binding = 1) writeonly buffer Values { float values[]; };

const vec3 kFaceDirections[6] = vec3[](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0),
                                       vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1));

void main() {
    const uint face = gl_LocalInvocationID.x;
    const uint cube = gl_WorkGroupID.x;
    // Compute shaders have no derivatives: explicit LOD.
    values[cube * 6 + face] = textureLod(cubes, vec4(kFaceDirections[face], float(cube)), 0.0).r;
}
