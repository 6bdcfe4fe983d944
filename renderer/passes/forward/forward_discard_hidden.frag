#version 460
#extension GL_GOOGLE_include_directive : require
// Forward shading for C that first discards fragments hidden in both eyes (Sect. 4.4).
#define MONOPLANE_DISCARD_HIDDEN_IN_EYES
#include "renderer/passes/forward/forward_shading.glsl"
