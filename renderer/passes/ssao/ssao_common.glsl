// Shared by the SSAO compute shaders (ssao_pass.h). Set 0 is the view being computed, set 1 the
// other eye of the pair (kPerView binds the same view twice and never reads set 1's maps).
// Pixel convention: pixel (i, j) of the area has NDC ((i + 0.5) / area.x * 2 - 1, likewise j),
// row 0 at the top (Vulkan clip y down); images are read texel-exact at integer pixels.
#include "renderer/passes/shared/view_constants.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, set = 0, binding = 0) uniform ViewBlock0 { ViewConstants view0; };
layout(std140, set = 1, binding = 0) uniform ViewBlock1 { ViewConstants view1; };
layout(set = 0, binding = 1) uniform sampler2D linear_depth0;  // metres in front of the eyes
layout(set = 1, binding = 1) uniform sampler2D linear_depth1;
// The visibility map L of papers/002 Sect. 3.1: for a pixel visible in both views, the nearest
// pixel p* of its projection into the other view (x | y << 16); kNotVisible otherwise.
layout(set = 0, binding = 2, r32ui) uniform uimage2D other_pixel0;
layout(set = 1, binding = 2, r32ui) uniform uimage2D other_pixel1;
layout(set = 0, binding = 3, r32f) uniform image2D raw_ao0;  // the estimate, before filtering
layout(set = 1, binding = 3, r32f) uniform image2D raw_ao1;
layout(set = 0, binding = 4, r32f) uniform image2D filtered_x0;  // the horizontal filter pass
layout(set = 1, binding = 4, r32f) uniform image2D filtered_x1;
layout(set = 0, binding = 5, r32f) uniform image2D ao0;  // the result

// Mirrors PushBlock in ssao_pass.cpp.
layout(push_constant) uniform Push {
    ivec2 area;  // the region drawn, from the top-left corner
    int directions;
    int steps;
    float radius;  // metres
    float angle_bias;
    float strength;
    float eta;
    float sigma_min;
    float sigma_max;
    float back_check_px;
    int taps;
    int flags;  // kFlag*
    // Linear depth beyond which the estimate is not computed (AO 1): in hybrid, pixels whose AO
    // is C's and lie far enough beyond m that no near pixel's filter weighs them.
    float skip_beyond;
} pc;

const int kFlagVertical = 1;   // the filter's second (vertical) pass
const int kFlagStereo = 2;     // the filter blends in the other view (papers/002 Sect. 3.3)
const int kFlagReproject = 4;  // the estimate takes the other view's value where L says so (3.2)

const uint kNotVisible = 0xffffffffu;
const float kPi = 3.14159265358979;

// What the shaders need of a view, gathered once per invocation.
struct Camera {
    mat4 view_proj;
    mat4 inv_view_proj;
    vec3 position;
    vec3 head_forward;    // shared by all views of the rig
    float depth_offset;   // the camera's own linear depth: dot(camera - head, head_forward)
    vec2 focal_px;        // pixels per unit of lateral offset over distance, in x and y
    vec3 camera_forward;  // the direction along which clip w measures distance
};
Camera cameras[2];

Camera make_camera(ViewConstants c) {
    Camera cam;
    cam.view_proj = c.view_proj;
    cam.inv_view_proj = c.inv_view_proj;
    cam.position = c.camera_position.xyz;
    cam.head_forward = c.head_forward.xyz;
    cam.depth_offset = dot(cam.position - c.head_position.xyz, cam.head_forward);
    // Rows of view_proj (glm and GLSL are column-major: m[column][row]). Clip w is the distance
    // along the camera's forward axis; the x and y rows, less their component along it (where a
    // sub-pixel jitter or an off-centre frustum lives), are the focal lengths in NDC units.
    mat4 m = c.view_proj;
    vec3 row_x = vec3(m[0][0], m[1][0], m[2][0]);
    vec3 row_y = vec3(m[0][1], m[1][1], m[2][1]);
    vec3 row_w = vec3(m[0][3], m[1][3], m[2][3]);
    vec3 f = normalize(row_w);
    cam.camera_forward = f;
    cam.focal_px = vec2(length(row_x - dot(row_x, f) * f), length(row_y - dot(row_y, f) * f)) *
                   0.5 * vec2(pc.area);
    return cam;
}

void load_cameras() {
    cameras[0] = make_camera(view0);
    cameras[1] = make_camera(view1);
}

bool in_area(ivec2 p) {
    return all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, pc.area));
}

bool is_sky(float depth) {
    return depth >= 0.5 * MONOPLANE_SKY_LINEAR_DEPTH;
}

float depth_at(int v, ivec2 p) {
    return v == 0 ? texelFetch(linear_depth0, p, 0).r : texelFetch(linear_depth1, p, 0).r;
}

uint other_pixel_at(int v, ivec2 p) {
    return v == 0 ? imageLoad(other_pixel0, p).r : imageLoad(other_pixel1, p).r;
}

ivec2 unpack_pixel(uint packed) {
    return ivec2(int(packed & 0xffffu), int(packed >> 16));
}

uint pack_pixel(ivec2 p) {
    return uint(p.x) | (uint(p.y) << 16);
}

// The world point of pixel p at linear depth d: along the ray from the camera through the pixel
// centre, where the distance in front of the eyes' plane is d.
vec3 world_at(int v, ivec2 p, float d) {
    vec2 ndc = (vec2(p) + 0.5) / vec2(pc.area) * 2.0 - 1.0;
    vec4 h = cameras[v].inv_view_proj * vec4(ndc, 0.5, 1.0);
    vec3 dir = h.xyz / h.w - cameras[v].position;
    float t = (d - cameras[v].depth_offset) / dot(dir, cameras[v].head_forward);
    return cameras[v].position + t * dir;
}

// Continuous pixel coordinates of a world point (pixel i spans [i, i + 1)) and its clip w;
// w <= 0 (behind the camera) yields coordinates outside every area.
vec3 to_pixel(int v, vec3 X) {
    vec4 c = cameras[v].view_proj * vec4(X, 1.0);
    if (c.w <= 1.0e-6) return vec3(-1.0e6, -1.0e6, c.w);
    return vec3((c.xy / c.w * 0.5 + 0.5) * vec2(pc.area), c.w);
}

float clip_w(int v, vec3 X) {
    return dot(X - cameras[v].position, cameras[v].camera_forward);
}

// The smaller of the forward and backward differences along `step` (HBAO+), so a depth edge on
// one side does not tilt the normal; zero when neither neighbour is a surface.
vec3 nearest_difference(int v, ivec2 p, ivec2 step, vec3 P) {
    vec3 best = vec3(0.0);
    float best_length = 3.0e38;
    ivec2 q = p + step;
    if (in_area(q)) {
        float d = depth_at(v, q);
        if (!is_sky(d)) {
            best = world_at(v, q, d) - P;
            best_length = dot(best, best);
        }
    }
    q = p - step;
    if (in_area(q)) {
        float d = depth_at(v, q);
        if (!is_sky(d)) {
            vec3 e = P - world_at(v, q, d);
            if (dot(e, e) < best_length) best = e;
        }
    }
    return best;
}

// The surface normal at P reconstructed from neighbouring positions (no normal buffer), facing
// the camera; towards the camera when the neighbourhood gives none.
vec3 normal_at(int v, ivec2 p, vec3 P) {
    vec3 to_camera = normalize(cameras[v].position - P);
    vec3 n = cross(nearest_difference(v, p, ivec2(1, 0), P),
                   nearest_difference(v, p, ivec2(0, 1), P));
    float length2 = dot(n, n);
    if (!(length2 > 0.0)) return to_camera;
    n *= inversesqrt(length2);
    return dot(n, to_camera) < 0.0 ? -n : n;
}

// The HBAO+ obscurance of a sample at V = S - P (the Alchemy AO estimator): the cosine to the
// normal less the bias, faded out towards the radius.
float obscurance(vec3 N, vec3 V) {
    float vv = dot(V, V);
    if (vv < 1.0e-12) return 0.0;
    float n_dot_v = dot(N, V) * inversesqrt(vv);
    float falloff = clamp(1.0 - vv / (pc.radius * pc.radius), 0.0, 1.0);
    return clamp(n_dot_v - pc.angle_bias, 0.0, 1.0) * falloff;
}

float ao_from_obscurance(float mean_obscurance) {
    return clamp(1.0 - pc.strength * mean_obscurance, 0.0, 1.0);
}

uint hash_uint(uint x) {  // "lowbias32" (Wellons)
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// Two numbers in [0, 1) from a key: the rotation of the directions and the jitter of the steps.
vec2 random2(uvec3 key) {
    uint h = hash_uint(key.x ^ hash_uint(key.y ^ hash_uint(key.z)));
    uint g = hash_uint(h ^ 0x9e3779b9u);
    return vec2(float(h >> 8), float(g >> 8)) * (1.0 / 16777216.0);
}
