#version 460
#extension GL_GOOGLE_include_directive : require
// The mono-to-stereo composite without velocity (no TAA).
#include "renderer/passes/composite/composite_body.glsl"
