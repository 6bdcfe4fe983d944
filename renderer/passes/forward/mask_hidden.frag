#version 460
#extension GL_GOOGLE_include_directive : require
// C's pixels hidden in both eyes (Fink et al. 2019, Sect. 4.4), marked in C's depth buffer before
// its depth pre-pass: every eye pixel that reads this part of C shows content nearer than m - eps,
// so the pixel gets the nearest depth (1 with reversed Z) and early depth testing rejects every
// fragment of the pre-pass, the chunks and the sky there: the paper's "Discarding Mono
// Fragments" without a fragment shader run (and a texture read) per fragment drawn. Geometry at
// exactly C's near plane also has depth 1 and passes the test: such a pixel is hidden anyway.
#include "renderer/passes/shared/view_block.glsl"
// The merged depth pyramid of both eyes (renderer/passes/depth_pyramid), mip 0 = level 2.
layout(set = 1, binding = 0) uniform sampler2D merged_depth;

void main() {
    if (texelFetch(merged_depth, ivec2(gl_FragCoord.xy) >> 2, 0).r <= view.view_blend.z) discard;
    gl_FragDepth = 1.0;
}
