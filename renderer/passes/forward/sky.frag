#version 460
#extension GL_GOOGLE_include_directive : require
// The sky of the eyes, and of C without the merged depth pyramid.
#include "renderer/passes/forward/sky_shading.glsl"
