#version 460
#extension GL_GOOGLE_include_directive : require
// Forward shading of every fragment that passes the depth test (every view).
#include "renderer/passes/forward/forward_shading.glsl"
