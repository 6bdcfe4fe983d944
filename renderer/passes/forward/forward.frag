#version 460
#extension GL_GOOGLE_include_directive : require
// Forward shading of every fragment (the eyes, and C without the merged depth pyramid).
#include "renderer/passes/forward/forward_shading.glsl"
