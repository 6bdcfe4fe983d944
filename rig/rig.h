// The triple-frustum camera rig of Fink et al. 2019, Sect. 3 and 4.1-4.2, for calibrated
// asymmetric frusta (docs/hybrid.md). Pure double-precision math: no Vulkan, no I/O.
//
// Symbols of the paper and their names here (head frame: +x right, +y up, -z forward, eyes at
// x = -d/2 and +d/2 in the plane z = 0):
//   d        RigInputs::ipd                 interpupillary distance
//   m        RigInputs::mono_plane          distance of the mono plane in front of the eyes
//   n, f     RigInputs::near, far           near and far of the eyes, from the eyes' plane
//   k        RigInputs::overlap_k           overlap constant (eq. 3), default 2
//   s        MonoCamera::offset_behind_eyes C's distance behind the eyes (|z_C| of eq. 1)
//   eps      Rig::overlap                   eps = k s m (eq. 3), or more for grazing surfaces
//   n_C, f_C MonoCamera::near, far          C's near and far, from C (eq. 4 plus s)
//   w_C, h_C MonoCamera::width, height      C's viewport (eq. 8), before rounding
//   W_C, H_C MonoCamera::allocated_*        C's allocation for the nearest selectable m
//   M_{C->E} Rig::mono_to_eye[e]            eq. 5, clip space of C -> clip space of eye e
//   M_{E->C} Rig::eye_to_mono[e]            eq. 5, the inverse
//   R_e      RigInputs::cant[e]             canted displays (docs/hybrid.md, beyond the
//                                           paper): eye e is turned by a yaw about the head's +y
//
// Canted eyes: the mono plane stays the head's plane z = -m. Each eye's cross-section with it is
// a quadrilateral; C's frustum contains both; the eyes' projections get an oblique far plane
// that IS the head's plane (their NDC depth 0 lies on it, as for parallel eyes), so eq. 5's
// M_{C->E} restricted to the plane is the plane-induced homography and everything built on it
// (composite, merged depth pyramid, C's pixel size) holds unchanged. With zero cant every output
// is bit-identical to the parallel rig.
#pragma once

#include <array>
#include <limits>

#include <glm/ext/matrix_double3x3.hpp>
#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double2.hpp>
#include <glm/ext/vector_double3.hpp>

#include "common/result.h"
#include "rig/tangents.h"

namespace monoplane::rig {

constexpr int kLeft = 0;
constexpr int kRight = 1;

// Tangents beyond this magnitude (84 degrees from the view axis) are refused as implausible.
// For canted eyes the same bound applies to the field's reach from the head's forward axis:
// beyond it the eye's cross-section with the mono plane grows without bound.
constexpr double kMaxTangent = 10.0;
// |cant| beyond this (radians, 45 degrees) is refused: no headset turns its displays further.
constexpr double kMaxCant = 0.7853981633974483;

struct RigInputs {
    std::array<Tangents, 2> eyes;  // [kLeft], [kRight], each in its eye's own (canted) frame
    int eye_width = 0;             // per-eye viewport in pixels (both eyes share it)
    int eye_height = 0;
    double ipd = 0.064;
    double mono_plane = 8.0;
    double near = 0.1;
    double far = 1000.0;
    double overlap_k = 2.0;
    // C's render target is allocated for this m (the nearest a user may select) and larger m use
    // a uv sub-range of it (Sect. 4.2). 0 means: allocate for mono_plane itself.
    double nearest_mono_plane = 0.0;
    // Surfaces down to this angle to the view rays (radians) show no cutting line at the plane:
    // the overlap grows from k s m to cover C's pixel footprint there, capped so that C's extra
    // near content stays within one eye pixel of near silhouettes (rig.cpp, docs/hybrid.md).
    // 0: the paper's eps = k s m alone.
    double grazing_angle = 0.017453292519943295;  // 1 degree
    // Yaw of each eye about the head's +y axis, radians, positive turning it left (OpenXR's
    // right-handed convention): a canted headset has cant[kLeft] > 0 > cant[kRight].
    std::array<double, 2> cant = {0.0, 0.0};
    bool operator==(const RigInputs&) const = default;
};

// True when either eye is canted (the rig then takes its general, non-affine paths).
bool is_canted(const RigInputs& inputs);

// R_e: eye e's orientation in the head frame (head-from-eye rotation).
glm::dmat3 eye_rotation(const RigInputs& inputs, int eye);

struct MonoCamera {
    double offset_behind_eyes = 0.0;  // s; C sits at (0, 0, +s) in the head frame
    Tangents tangents;                // C's frustum: both eyes' cross-sections at m inside it
    double near = 0.0;                // n_C = m - eps + s, from C
    double far = 0.0;                 // f_C = f + s, from C
    double width = 0.0;               // w_C of eq. 8, pixels, before rounding
    double height = 0.0;              // h_C
    int viewport_width = 0;           // ceil(w_C): the pixels C renders
    int viewport_height = 0;
    int allocated_width = 0;  // ceil(W_C) for nearest_mono_plane (and any larger m)
    int allocated_height = 0;
    glm::dvec2 uv_scale{1.0};  // viewport / allocation: C's image is uv in [0, uv_scale]
    // C's reversed-Z NDC depth of the mono plane (distance m + s from C): the depth of the quad Q
    // of eq. 6 in monoplane, which maps C's image into the eyes through the mono plane rather
    // than through C's near plane (docs/rig.md). The eyes' NDC depth of the plane is 0 (far = m).
    double mono_plane_ndc_depth = 0.0;
};

struct Rig {
    RigInputs inputs;
    // True when m >= f: nothing lies beyond the plane, C is skipped and hybrid equals stereo.
    // Then every MonoCamera field, overlap and mono_position are zero, mono_to_eye and
    // eye_to_mono are identities, and eye_projection spans n..f.
    bool mono_skipped = false;
    MonoCamera mono;
    double overlap = 0.0;                     // eps
    std::array<glm::dvec3, 2> eye_positions;  // head frame
    glm::dvec3 mono_position{0.0};            // head frame, (0, 0, s)
    // Head frame -> eye e's view frame (rotation R_e^T after the translation by -eye position).
    std::array<glm::dmat4, 2> eye_from_head;
    // Reversed-Z Vulkan projections (rig/projection.h): the eyes' near passes cover
    // n..m, C covers n_C..f_C. A canted eye's far plane is oblique: the head's plane z = -m.
    std::array<glm::dmat4, 2> eye_projection;
    glm::dmat4 mono_projection{1.0};
    // Clip-space mappings of eq. 5 in the head frame. M_{C->E} maps C's clip coordinates of a
    // point to eye e's clip coordinates of the same point.
    std::array<glm::dmat4, 2> mono_to_eye;
    std::array<glm::dmat4, 2> eye_to_mono;
    // Supremum over depth (reached at infinity), over both eyes and their whole field, of the
    // offset between where a point beyond m appears in hybrid and in stereo (Fig. 2, right).
    double max_error_px = 0.0;     // horizontal (the disparity error the paper plots)
    double max_error_px_2d = 0.0;  // Euclidean, including the small vertical magnification
};

// Builds the rig, or a clear error naming the offending input: m <= n, n <= 0, non-finite numbers,
// tangents of the wrong sign or beyond kMaxTangent, sizes < 1, ipd < 0, n >= f, k < 0, an
// overlap that would reach the eyes' plane (k s >= 1), nearest_mono_plane outside (n, m], a cant
// beyond kMaxCant, a canted field reaching beyond kMaxTangent from the head's axis, an eye's
// outer edge turned past the head's axis (no C behind the eyes then).
// m >= f is not an error: the rig comes back with mono_skipped set and zero error.
// May be called at any time; pure.
Result<Rig> build_rig(const RigInputs& inputs);

struct PixelError {
    double horizontal_px = 0.0;
    double vertical_px = 0.0;
    double euclidean_px = 0.0;
};

// A depth at infinity, which the functions below that take a depth accept (the supremum over
// depth).
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The largest offset, over both eyes and their field of view, of a point at `depth` (metres in
// front of the eyes' plane) between hybrid and stereo. Parallel eyes: closed form (the maximum
// is at a corner of the field). Canted eyes: the maximum over a 65 x 65 grid of each eye's field
// (edges and corners included) of the exact offset. Zero for depth <= m (stereo content) and
// for a skipped C; depth may be +infinity (the supremum: max_error_px, max_error_px_2d).
PixelError error_at_depth(const Rig& rig, double depth);

// Where a point (head frame) appears in eye e, in pixels (x right, y down, pixel centres at
// i + 0.5): directly (stereo), and through C and the mono plane (hybrid: the central projection
// from C onto z = -m, then seen by the eye; what hybrid shows for points beyond m, for any depth
// in front of C; equal to stereo when mono_skipped). The point must lie in front of the eye.
glm::dvec2 eye_pixel_stereo(const Rig& rig, int eye, const glm::dvec3& point);
glm::dvec2 eye_pixel_hybrid(const Rig& rig, int eye, const glm::dvec3& point);

// The homography from C's pixels (x right, y down over its viewport_width x viewport_height
// viewport, centres at i + 0.5) to eye e's pixels, through the mono plane: eq. 5's M_{C->E}
// restricted to C's points at the plane's depth. An eye pixel q reads C at the inverse image of q,
// so this tells which eye pixels read a region of C (the merged depth pyramid, Sect. 4.4).
// Column-major like glm: apply as h = H * (x, y, 1), pixel = h.xy / h.z. Identity when
// mono_skipped.
glm::dmat3 mono_pixel_to_eye_pixel(const Rig& rig, int eye);

// Eq. 9's (1/2) S for eye e: the diagonal factors turning a screen-space velocity in C's NDC
// into the eye's NDC, v_E = (1/2) S v_C, with S = diag(x_q10 - x_q00, y_q01 - y_q00) from C's
// quad Q (eq. 6) mapped into the eye (eq. 7) and dehomogenised. Q lies on the mono plane, as in
// the composite (see MonoCamera::mono_plane_ndc_depth); the cameras share their orientation, so
// the mapping between the planes is affine and S the same everywhere. (1, 1) when mono_skipped.
// Canted eyes: the mapping is projective and no constant S exists; the composite then uses the
// homography's Jacobian per pixel (composite_body.glsl), and this returns S at C's centre.
glm::dvec2 mono_velocity_to_eye(const Rig& rig, int eye);

// The largest reversed-Z NDC depth, over both eyes' fields, of the head's plane at `distance`
// (n < distance <= m) in front of the eyes: an eye depth above it is nearer than that plane in
// every pixel. For parallel eyes the plane's depth is the same in every pixel. Zero when
// mono_skipped.
double nearest_eye_depth_of_plane(const Rig& rig, double distance);

}  // namespace monoplane::rig
