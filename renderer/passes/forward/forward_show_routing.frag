#version 460
#extension GL_GOOGLE_include_directive : require
// The debug view "routing": forward shading, recoloured by the lists the chunk went to.
#define MONOPLANE_SHOW_ROUTING
#include "renderer/passes/forward/forward_shading.glsl"
