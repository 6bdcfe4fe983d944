#version 460
#extension GL_GOOGLE_include_directive : require
// C's sky, skipping pixels hidden in both eyes (Sect. 4.4).
#define MONOPLANE_DISCARD_HIDDEN_IN_EYES
#include "renderer/passes/forward/sky_shading.glsl"
