#version 460
#extension GL_GOOGLE_include_directive : require
// composite.frag writing the eye's display image: C's colour tone mapped where the eye drew
// nothing (CompositePass::record_display; composite_near.frag tone maps the rest).
#define MONOPLANE_WRITE_DISPLAY
#include "renderer/passes/composite/composite_body.glsl"
