#version 460
#extension GL_GOOGLE_include_directive : require
#include "renderer/passes/forward/forward_vertex.glsl"
