#version 460
#extension GL_GOOGLE_include_directive : require
// sky_discard_hidden.frag plus the screen-space velocity TAA reprojects with (Karis 2014).
#define MONOPLANE_WRITE_VELOCITY
#define MONOPLANE_DISCARD_HIDDEN_IN_EYES
#include "renderer/passes/forward/sky_shading.glsl"
