// The push constants of the G-buffer pass (shaders/shared/push_constants.h, GBufferPush), for
// both of its stages.
#include "shared/push_constants.h"
layout(push_constant) uniform GBufferPushBlock { GBufferPush pc; };
