#version 460
// Test shader: y = a·x + y over n floats (tests/gpu). `precise` forbids fusing into an FMA, so
// the result is bit-identical to the CPU's separate multiply and add.
layout(local_size_x = 256) in;

layout(std430, set = 0, binding = 0) readonly buffer X { float x[]; };
layout(std430, set = 0, binding = 1) buffer Y { float y[]; };

layout(push_constant) uniform Params {
    float a;
    uint n;
} params;

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= params.n) return;
    precise float ax = params.a * x[i];
    precise float result = ax + y[i];
    y[i] = result;
}
