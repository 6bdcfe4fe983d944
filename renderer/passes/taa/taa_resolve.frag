#version 460
#extension GL_GOOGLE_include_directive : require
// Temporal anti-aliasing after Karis 2014 ("High-quality temporal supersampling"), as Fink et al.
// 2019 adapt it in Sect. 4.5: the history is reprojected with the velocity of the nearest pixel
// of the 3x3 neighbourhood, read with a Catmull-Rom filter, clipped towards the neighbourhood's
// colour box in YCoCg, and blended exponentially. All of it in a reversibly tone-mapped space
// c / (1 + max(c)), so a bright sky pixel cannot dominate an edge (Karis' luma weighting).
// The colour box is widened with the pixel's screen-space velocity (Sect. 4.5): C's image,
// mapped bilinearly into the eye, has narrower neighbourhoods than a rendered image, and a
// narrow box clips away the very history that removes the aliasing.
layout(set = 0, binding = 0) uniform sampler2D current;       // the eye's HDR, texel-exact
layout(set = 0, binding = 1) uniform sampler2D velocity;      // NDC now minus NDC before
layout(set = 0, binding = 2) uniform sampler2D linear_depth;  // for the nearest neighbour
layout(set = 0, binding = 3) uniform sampler2D history;       // last output, bilinear, clamped
layout(push_constant) uniform Push {
    vec4 params;  // x: history weight; y: box widening per pixel of motion; z: 1 = reset history
    vec4 extent;  // xy: size in pixels; zw: 1 / size
};
layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

vec3 compress(vec3 c) { return c / (1.0 + max(c.r, max(c.g, c.b))); }
vec3 expand(vec3 t) { return t / max(1.0 - max(t.r, max(t.g, t.b)), 1e-4); }

vec3 to_ycocg(vec3 c) {
    return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b,
                -0.25 * c.r + 0.5 * c.g - 0.25 * c.b);
}
vec3 from_ycocg(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

// Catmull-Rom over 4x4 texels in 9 bilinear taps: sharper than bilinear, so a static history is
// not blurred a little more every frame.
vec3 history_catmull_rom(vec2 uv) {
    vec2 size = extent.xy;
    vec2 position = uv * size;
    vec2 centre = floor(position - 0.5) + 0.5;
    vec2 f = position - centre;
    vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
    vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
    vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
    vec2 w3 = f * f * (-0.5 + 0.5 * f);
    vec2 w12 = w1 + w2;
    vec2 uv0 = (centre - 1.0) * extent.zw;
    vec2 uv12 = (centre + w2 / w12) * extent.zw;
    vec2 uv3 = (centre + 2.0) * extent.zw;
    vec3 sum = texture(history, vec2(uv0.x, uv0.y)).rgb * (w0.x * w0.y) +
               texture(history, vec2(uv12.x, uv0.y)).rgb * (w12.x * w0.y) +
               texture(history, vec2(uv3.x, uv0.y)).rgb * (w3.x * w0.y) +
               texture(history, vec2(uv0.x, uv12.y)).rgb * (w0.x * w12.y) +
               texture(history, vec2(uv12.x, uv12.y)).rgb * (w12.x * w12.y) +
               texture(history, vec2(uv3.x, uv12.y)).rgb * (w3.x * w12.y) +
               texture(history, vec2(uv0.x, uv3.y)).rgb * (w0.x * w3.y) +
               texture(history, vec2(uv12.x, uv3.y)).rgb * (w12.x * w3.y) +
               texture(history, vec2(uv3.x, uv3.y)).rgb * (w3.x * w3.y);
    return max(sum, vec3(0.0));  // the negative lobes may undershoot
}

// Karis' clip: moves the history towards the box centre until it lies inside the box.
vec3 clip_to_box(vec3 centre, vec3 half_extent, vec3 value) {
    vec3 offset = value - centre;
    vec3 units = abs(offset / max(half_extent, vec3(1e-6)));
    float outside = max(units.x, max(units.y, units.z));
    return outside > 1.0 ? centre + offset / outside : value;
}

void main() {
    ivec2 size = ivec2(extent.xy);
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 current_color = texelFetch(current, pixel, 0).rgb;
    if (params.z > 0.5) {
        out_color = vec4(current_color, 1.0);
        return;
    }
    vec3 box_min = vec3(1e30);
    vec3 box_max = vec3(-1e30);
    float nearest = 3.0e38;
    ivec2 nearest_pixel = pixel;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = clamp(pixel + ivec2(dx, dy), ivec2(0), size - 1);
            vec3 c = to_ycocg(compress(texelFetch(current, q, 0).rgb));
            box_min = min(box_min, c);
            box_max = max(box_max, c);
            float d = texelFetch(linear_depth, q, 0).r;
            if (d < nearest) {
                nearest = d;
                nearest_pixel = q;
            }
        }
    }
    // The nearest surface's motion (Karis): edges of near objects carry their own history.
    vec2 motion_uv = 0.5 * texelFetch(velocity, nearest_pixel, 0).xy;
    vec2 previous_uv = in_uv - motion_uv;
    if (any(lessThan(previous_uv, vec2(0.0))) || any(greaterThan(previous_uv, vec2(1.0)))) {
        out_color = vec4(current_color, 1.0);  // off screen last frame: no history
        return;
    }
    float motion_px = length(motion_uv * extent.xy);
    vec3 centre = 0.5 * (box_max + box_min);
    vec3 half_extent = 0.5 * (box_max - box_min) * (1.0 + params.y * min(motion_px, 1.0));
    vec3 previous = to_ycocg(compress(history_catmull_rom(previous_uv)));
    previous = clip_to_box(centre, half_extent, previous);
    vec3 blended = mix(to_ycocg(compress(current_color)), previous, params.x);
    out_color = vec4(expand(from_ycocg(blended)), 1.0);
}
