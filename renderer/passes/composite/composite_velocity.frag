#version 460
#extension GL_GOOGLE_include_directive : require
// composite.frag plus C's screen-space velocity mapped into the eye (TAA, eq. 9).
#define MONOPLANE_WRITE_VELOCITY
#include "renderer/passes/composite/composite_body.glsl"
