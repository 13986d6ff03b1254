// Test include (tests/gpu): resolved from the embedded shaders by compile_glsl.
const float kIncludedValue = 4.5;
