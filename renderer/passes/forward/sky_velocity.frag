#version 460
#extension GL_GOOGLE_include_directive : require
// sky.frag plus the screen-space velocity TAA reprojects with (Karis 2014).
#define MONOPLANE_WRITE_VELOCITY
#include "renderer/passes/forward/sky_shading.glsl"
