#version 460
#extension GL_GOOGLE_include_directive : require
// The debug view "routing": also passes each draw's chunk index on.
#define MONOPLANE_SHOW_ROUTING
#include "renderer/passes/forward/forward_vertex.glsl"
