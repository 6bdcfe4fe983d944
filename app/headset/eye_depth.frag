#version 460
#extension GL_GOOGLE_include_directive : require
// An eye's depth for XR_KHR_composition_layer_depth (eye_depth_writer.h): the renderer's linear
// depth (metres in front of the eyes' plane, along the head's forward axis) becomes the distance
// along the eye's own view axis, encoded reversed-Z with the far plane at infinity,
// d = near / distance (the layer says minDepth 0, maxDepth 1, nearZ = +inf, farZ = near).
#include "app/headset/eye_depth_constants.h"
#include "renderer/passes/shared/view_constants.h"

layout(set = 0, binding = 0) uniform sampler2D linear_depth;  // read texel-exact
layout(push_constant) uniform Push { EyeDepthConstants c; };
layout(location = 0) in vec2 in_uv;  // pixel centre / size, y down

// Beyond any far plane: the sky, also averaged with a surface by an MSAA resolve (at least an
// eighth of MONOPLANE_SKY_LINEAR_DEPTH then).
const float kSkyDepth = float(MONOPLANE_SKY_LINEAR_DEPTH) * 1e-10;

void main() {
    ivec2 size = textureSize(linear_depth, 0);
    ivec2 texel = clamp(ivec2(in_uv * vec2(size)), ivec2(0), size - 1);
    float plane_depth = texelFetch(linear_depth, texel, 0).r;
    // The pixel's ray in the eye's frame, scaled to one metre along the eye's axis (-z), and in
    // the head's. A point at distance s along the eye's axis on this ray lies
    // s * forward + offset in front of the eyes' plane, so s = (plane depth - offset) / forward.
    vec3 ray_eye = vec3(mix(c.tangents.x, c.tangents.y, in_uv.x),
                        mix(c.tangents.z, c.tangents.w, in_uv.y), -1.0);
    float forward = -(mat3(c.eye_to_head) * ray_eye).z;
    float distance = (plane_depth - c.encoding.y) / forward;
    // Sky, or no point in front of the eye: infinitely far, window depth 0. Nearer than near
    // (clipped by the renderer anyway): 1.
    bool infinite = !(plane_depth < kSkyDepth) || !(forward > 0.0) || !(distance > 0.0);
    gl_FragDepth = infinite ? 0.0 : min(c.encoding.x / distance, 1.0);
}
