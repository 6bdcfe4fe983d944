// The composite's push constants (CompositePass's PushBlock, std430, 128 bytes): one block for
// every pipeline of the pass, so that they share one pipeline layout.
layout(push_constant) uniform Push {
    mat4 eye_to_mono;       // M_{E->C} of eq. 5, eye clip space -> C's clip space
    vec4 uv_limits;         // xy: C's uv sub-range (eq. 8 viewport / allocation); zw: half a texel
    vec4 eye_extent_mode;   // xy: eye size in pixels; z: mapping; w: tint of the mono region
    vec4 offset_exposure;   // xy: integer offset of the engine-style copy (papers/003);
                            // z: exposure, when the pass writes the display image
    vec4 velocity_scale;    // xy: C's NDC velocity -> the eye's, 1/2 S of eq. 9 (diagonal)
};
