#version 460
#extension GL_GOOGLE_include_directive : require
// forward_show_routing.frag plus the screen-space velocity TAA reprojects with (Karis 2014).
#define MONOPLANE_WRITE_VELOCITY
#define MONOPLANE_SHOW_ROUTING
#include "renderer/passes/forward/forward_shading.glsl"
