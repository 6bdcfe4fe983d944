#version 460
#extension GL_GOOGLE_include_directive : require
// The sky of every view (C's pixels hidden in both eyes are rejected by mask_hidden.frag's depth).
#include "renderer/passes/forward/sky_shading.glsl"
