// The triple-frustum rig of Fink et al. 2019 (papers/000, Sect. 3, 4.1, 4.2); docs/hybrid.md
// ("The camera rig") maps every equation to the names used here. All distances are metres, all
// tangents XrFovf-style.
#include "rig/rig.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include <glm/ext/matrix_double3x4.hpp>
#include <glm/ext/matrix_double4x3.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/ext/vector_int2.hpp>

#include "common/programming_error.h"
#include "rig/projection.h"

namespace monoplane::rig {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string number(double value) {
    std::ostringstream text;
    text.precision(10);
    text << value;
    return text.str();
}

const char* eye_name(int eye) {
    return eye == kLeft ? "left" : "right";
}

// x of eye e in the head frame: the eyes sit at -d/2 and +d/2.
double eye_x(const RigInputs& inputs, int eye) {
    return eye == kLeft ? -0.5 * inputs.ipd : 0.5 * inputs.ipd;
}

// A direction of eye e's field, (tan_x, tan_y, -1) in the eye's frame, in the head frame.
glm::dvec3 ray_in_head(const RigInputs& in, int eye, double tan_x, double tan_y) {
    return eye_rotation(in, eye) * glm::dvec3(tan_x, tan_y, -1.0);
}

// The four corner directions of eye e's field, head frame.
std::array<glm::dvec3, 4> corner_rays(const RigInputs& in, int eye) {
    const Tangents& t = in.eyes[eye];
    return {ray_in_head(in, eye, t.left, t.down), ray_in_head(in, eye, t.right, t.down),
            ray_in_head(in, eye, t.left, t.up), ray_in_head(in, eye, t.right, t.up)};
}

// s: the outer frustum planes of the eyes cross the z axis behind the eyes (eq. 1, z_C = -s).
// The left eye's outer edge, direction r = R_L (tan_left, 0, -1) from x = -d/2, meets x = 0 at
// z = (d/2) r_z / r_x (positive: behind the eyes); for a parallel eye that is d / (2 -tan_left).
// The right's likewise at (d/2) r_z / -r_x. C takes the farther back, so that both outer planes
// pass in front of it and its frustum can contain both eyes' fields.
double offset_behind_eyes(const RigInputs& inputs) {
    const glm::dvec3 left_edge = ray_in_head(inputs, kLeft, inputs.eyes[kLeft].left, 0.0);
    const glm::dvec3 right_edge = ray_in_head(inputs, kRight, inputs.eyes[kRight].right, 0.0);
    const double half_ipd = 0.5 * inputs.ipd;
    const double left_crossing_behind = half_ipd * left_edge.z / left_edge.x;
    const double right_crossing_behind = half_ipd * right_edge.z / -right_edge.x;
    return std::max(left_crossing_behind, right_crossing_behind);
}

// The problem with eye e's tangents, if any: finite, within kMaxTangent, XrFovf's signs.
std::optional<std::string> tangent_problem(const Tangents& t, int eye) {
    const std::string prefix = std::string("eyes[") + eye_name(eye) + "].";
    const std::pair<const char*, double> sides[] = {
        {"tan_left", t.left}, {"tan_right", t.right}, {"tan_down", t.down}, {"tan_up", t.up}};
    for (const auto& [side, value] : sides) {
        const std::string name = prefix + side;
        if (!std::isfinite(value)) return name + " is not a finite number";
        if (std::abs(value) > kMaxTangent) {
            return name + " = " + number(value) + " exceeds the sane bound of " +
                   number(kMaxTangent) + " (84 degrees from the view axis)";
        }
    }
    if (!(t.left < 0.0)) {
        return prefix + "tan_left = " + number(t.left) +
               " must be negative (XrFovf convention: left of the view axis)";
    }
    if (!(t.right > 0.0)) return prefix + "tan_right = " + number(t.right) + " must be positive";
    if (!(t.down < 0.0)) {
        return prefix + "tan_down = " + number(t.down) +
               " must be negative (XrFovf convention: +y is up)";
    }
    if (!(t.up > 0.0)) return prefix + "tan_up = " + number(t.up) + " must be positive";
    return std::nullopt;
}

// The problem with eye e's cant, if any: the bound on the angle, the field's reach from the head's
// forward axis (the cross-section with the plane must stay bounded), and the outer edge, which
// must still point outwards for C to sit behind the eyes.
std::optional<std::string> cant_problem(const RigInputs& in, int eye) {
    const std::string name = std::string("cant[") + eye_name(eye) + "]";
    const double cant = in.cant[eye];
    if (!std::isfinite(cant)) return name + " is not a finite number";
    if (std::abs(cant) > kMaxCant) {
        return name + " = " + number(cant * 180.0 / kPi) + " degrees exceeds the bound of " +
               number(kMaxCant * 180.0 / kPi) + " degrees";
    }
    if (cant == 0.0) return std::nullopt;
    const glm::dvec3 outer = eye == kLeft ? ray_in_head(in, eye, in.eyes[eye].left, 0.0)
                                          : ray_in_head(in, eye, in.eyes[eye].right, 0.0);
    if (eye == kLeft ? !(outer.x < 0.0) : !(outer.x > 0.0)) {
        return std::string("the ") + eye_name(eye) + " eye is turned inwards by " +
               number(std::abs(cant) * 180.0 / kPi) +
               " degrees, past its outer field edge: its outer frustum plane no longer crosses "
               "behind the eyes, so there is no place for C";
    }
    for (const glm::dvec3& r : corner_rays(in, eye)) {
        const double reach = std::hypot(r.x, r.y) / -r.z;
        if (!(r.z < 0.0) || reach > kMaxTangent) {
            return std::string("the ") + eye_name(eye) + " eye's field, turned by " +
                   number(cant * 180.0 / kPi) +
                   " degrees, reaches beyond 84 degrees from the head's forward axis, where its "
                   "cross-section with the mono plane is unbounded "
                   "(docs/hybrid.md, \"Canted displays\")";
        }
    }
    return std::nullopt;
}

// The first problem with the inputs, naming the input; nullopt when they are usable.
std::optional<Error> validate(const RigInputs& in) {
    auto problem = [](const std::string& text) { return Error{"camera rig: " + text}; };
    const std::pair<const char*, double> scalars[] = {
        {"ipd (d)", in.ipd},
        {"mono_plane (m)", in.mono_plane},
        {"near (n)", in.near},
        {"far (f)", in.far},
        {"overlap_k (k)", in.overlap_k},
        {"nearest_mono_plane", in.nearest_mono_plane},
        {"grazing_angle", in.grazing_angle},
    };
    for (const auto& [name, value] : scalars) {
        if (!std::isfinite(value)) return problem(std::string(name) + " is not a finite number");
    }
    for (int eye : {kLeft, kRight}) {
        if (std::optional<std::string> text = tangent_problem(in.eyes[eye], eye)) {
            return problem(*text);
        }
    }
    for (int eye : {kLeft, kRight}) {
        if (std::optional<std::string> text = cant_problem(in, eye)) return problem(*text);
    }
    if (in.eye_width < 1) {
        return problem("eye_width = " + std::to_string(in.eye_width) + " must be at least 1 pixel");
    }
    if (in.eye_height < 1) {
        return problem("eye_height = " + std::to_string(in.eye_height) +
                       " must be at least 1 pixel");
    }
    if (in.ipd < 0.0) return problem("ipd (d) = " + number(in.ipd) + " must not be negative");
    if (!(in.near > 0.0)) return problem("near (n) = " + number(in.near) + " must be positive");
    if (!(in.far > in.near)) {
        return problem("far (f) = " + number(in.far) +
                       " must be greater than near (n) = " + number(in.near));
    }
    if (!(in.mono_plane > in.near)) {
        return problem("mono_plane (m) = " + number(in.mono_plane) +
                       " must be greater than near (n) = " + number(in.near) +
                       ": the eyes render the range n..m");
    }
    if (in.grazing_angle < 0.0 || in.grazing_angle >= 0.25 * kPi) {
        return problem("grazing_angle = " + number(in.grazing_angle * 180.0 / kPi) +
                       " degrees must lie in [0, 45): 0 keeps the paper's overlap k s m");
    }
    if (in.overlap_k < 0.0) {
        return problem("overlap_k (k) = " + number(in.overlap_k) + " must not be negative");
    }
    if (in.nearest_mono_plane != 0.0 &&
        !(in.nearest_mono_plane > in.near && in.nearest_mono_plane <= in.mono_plane)) {
        return problem("nearest_mono_plane = " + number(in.nearest_mono_plane) +
                       " must lie in (near, mono_plane] = (" + number(in.near) + ", " +
                       number(in.mono_plane) + "], or be 0 for mono_plane itself");
    }
    // eps = k s m (eq. 3) puts C's near plane at m - eps = m (1 - k s) from the eyes; for k s >= 1
    // it would sit at or behind the eyes' plane (at or behind C for some m), whatever m is.
    const double s = offset_behind_eyes(in);
    if (in.overlap_k * s >= 1.0) {
        return problem(
            "overlap_k (k) = " + number(in.overlap_k) + " with s = " + number(s) +
            " m (from ipd and the outer tangents) gives k s = " + number(in.overlap_k * s) +
            " >= 1: the overlap eps = k s m would reach behind the eyes");
    }
    return std::nullopt;
}

// The exact inverse of projection_reversed_z (rig/projection.cpp), written out rather
// than computed by glm::inverse so that M_{C->E} and M_{E->C} are inverses to rounding.
// From clip (x_c, y_c, z_c, w_c): z = -w_c, x = (x_c - b z) / a, y = (y_c - e z) / c, and the
// homogeneous w = (z_c - A z) / B, with a, b, c, e, A, B the entries of the projection.
glm::dmat4 inverse_projection_reversed_z(const Tangents& t, double near, double far) {
    const double a = 2.0 / (t.right - t.left);
    const double b = (t.right + t.left) / (t.right - t.left);
    const double c = -2.0 / (t.up - t.down);
    const double e = -(t.up + t.down) / (t.up - t.down);
    const double depth_scale = near / (far - near);         // A
    const double depth_offset = near * far / (far - near);  // B
    glm::dmat4 inverse(0.0);                                // column-major: inverse[column][row]
    inverse[0][0] = 1.0 / a;
    inverse[3][0] = b / a;
    inverse[1][1] = 1.0 / c;
    inverse[3][1] = e / c;
    inverse[3][2] = -1.0;
    inverse[2][3] = 1.0 / depth_offset;
    inverse[3][3] = depth_scale / depth_offset;
    return inverse;
}

// Everything that depends on m alone (given the other inputs): C, the projections and eq. 5.
// Called once for m and once for the nearest selectable m (the allocation, Sect. 4.2).
struct Cameras {
    double s = 0.0;
    double overlap = 0.0;
    Tangents mono_tangents;
    double mono_near = 0.0;
    double mono_far = 0.0;
    std::array<glm::dvec3, 2> eye_positions;
    glm::dvec3 mono_position{0.0};
    std::array<glm::dmat4, 2> eye_projection;
    glm::dmat4 mono_projection{1.0};
    std::array<glm::dmat4, 2> mono_to_eye;
    std::array<glm::dmat4, 2> eye_to_mono;
    double mono_plane_ndc_depth = 0.0;
    glm::dvec2 mono_size{0.0};  // w_C, h_C (eq. 8)
};

// Eye e's projection for its near pass, n..m: for a parallel eye the standard reversed-Z one with
// far = m. For a canted eye the far plane is made oblique so that it is the head's plane
// z_head = -m: in the eye's frame that plane is n_e . p + m = 0 with n_e = R_e^T z (the head's z
// axis seen from the eye), so the depth row k (n_e . p + m) puts NDC depth 0 exactly on it, and
// k = n / (m - n n_e.z) keeps depth 1 at distance n on the eye's axis. Depth is still monotonic
// along every ray (it is k n_e.r / -r_z + k m / (t -r_z) for p = t r), so the depth test and
// perspective-correct interpolation work as before (an oblique clipping plane in the sense of
// Lengyel 2005, here the far one).
glm::dmat4 eye_near_pass_projection(const RigInputs& in, int eye, double m) {
    glm::dmat4 p = projection_reversed_z(in.eyes[eye], in.near, m);
    if (in.cant[eye] == 0.0) return p;
    const glm::dvec3 n_e = glm::transpose(eye_rotation(in, eye)) * glm::dvec3(0.0, 0.0, 1.0);
    const double k = in.near / (m - in.near * n_e.z);
    p[0][2] = k * n_e.x;  // glm: p[column][row]
    p[1][2] = k * n_e.y;
    p[2][2] = k * n_e.z;
    p[3][2] = k * m;
    return p;
}

glm::dmat4 eye_from_head_matrix(const RigInputs& in, int eye) {
    glm::dmat4 rotation(glm::transpose(eye_rotation(in, eye)));
    return rotation * glm::translate(glm::dmat4(1.0), -glm::dvec3(eye_x(in, eye), 0.0, 0.0));
}

// C's frustum (eq. 2's geometric meaning, docs/hybrid.md): the slopes from C, at distance
// m + s from the mono plane, to the outermost points of the eyes' cross-sections with the plane.
// A cross-section is the quadrilateral of the eye's four corner rays met with z = -m; C's
// frustum is a rectangle in its tangents, so containing the eight corners contains both
// quadrilaterals. For a parallel eye the corner x + tan m and vertical tan m reproduce the
// paper's rectangle, whose vertical tangents shrink by m / (m + s).
Tangents mono_frustum(const RigInputs& in, double m, double s) {
    const double from_mono = m + s;
    Tangents ct{kInfinity, -kInfinity, kInfinity, -kInfinity};
    for (int eye : {kLeft, kRight}) {
        const double x = eye_x(in, eye);
        for (const glm::dvec3& r : corner_rays(in, eye)) {
            const double to_plane = m / -r.z;  // exactly m for a parallel eye (r.z = -1)
            const double left_right = (x + r.x * to_plane) / from_mono;
            const double down_up = r.y * to_plane / from_mono;
            ct.left = std::min(ct.left, left_right);
            ct.right = std::max(ct.right, left_right);
            ct.down = std::min(ct.down, down_up);
            ct.up = std::max(ct.up, down_up);
        }
    }
    return ct;
}

// Eye e's pixels per unit of C's NDC along x and y, at C's NDC point (x, y) on the mono plane
// (the diagonal of the homography's Jacobian).
glm::dvec2 eye_pixels_per_mono_ndc(const RigInputs& in, const glm::dmat4& mono_to_eye, double x,
                                   double y, double z) {
    const glm::dvec4 h = mono_to_eye * glm::dvec4(x, y, z, 1.0);
    const glm::dvec2 q = glm::dvec2(h) / h.w;
    const glm::dvec2 d_dx = (glm::dvec2(mono_to_eye[0]) - q * mono_to_eye[0].w) / h.w;
    const glm::dvec2 d_dy = (glm::dvec2(mono_to_eye[1]) - q * mono_to_eye[1].w) / h.w;
    return glm::dvec2(std::abs(d_dx.x) * 0.5 * in.eye_width,
                      std::abs(d_dy.y) * 0.5 * in.eye_height);
}

// C's cameras for mono plane m with overlap eps. C's frustum and pixel size do not depend on eps
// (they are fixed by the plane), only its near plane does.
// eq. 5 in the head frame for eye e: C shares the head's orientation, so V_E V_C^-1 is the
// translation by C's position as seen from the eye (p_C - p_E) followed by the eye's rotation
// R_e^T, and its inverse the reverse. Fills c.eye_projection, mono_to_eye and eye_to_mono.
void map_mono_to_eye(const RigInputs& in, double m, int eye, Cameras& c) {
    const glm::dmat4 mono_projection_inverse =
        inverse_projection_reversed_z(c.mono_tangents, c.mono_near, c.mono_far);
    c.eye_projection[eye] = eye_near_pass_projection(in, eye, m);
    if (in.cant[eye] == 0.0) {
        // The plain translation and the exact hand-written inverse, so that a parallel rig is
        // bit-identical to the one before canted eyes existed.
        const glm::dmat4 eye_projection_inverse =
            inverse_projection_reversed_z(in.eyes[eye], in.near, m);
        const glm::dvec3 mono_in_eye_view = c.mono_position - c.eye_positions[eye];
        c.mono_to_eye[eye] = c.eye_projection[eye] *
                             glm::translate(glm::dmat4(1.0), mono_in_eye_view) *
                             mono_projection_inverse;
        c.eye_to_mono[eye] = c.mono_projection *
                             glm::translate(glm::dmat4(1.0), -mono_in_eye_view) *
                             eye_projection_inverse;
        return;
    }
    const glm::dmat4 eye_from_head = eye_from_head_matrix(in, eye);
    const glm::dmat4 eye_from_mono_view =
        eye_from_head * glm::translate(glm::dmat4(1.0), c.mono_position);
    const glm::dmat4 mono_view_from_eye =
        glm::translate(glm::dmat4(1.0), -c.mono_position) * glm::inverse(eye_from_head);
    c.mono_to_eye[eye] = c.eye_projection[eye] * eye_from_mono_view * mono_projection_inverse;
    c.eye_to_mono[eye] =
        c.mono_projection * mono_view_from_eye * glm::inverse(c.eye_projection[eye]);
}

// w_C, h_C of eq. 8 as eye e would have them, before the smaller of the two eyes is taken. The
// quad Q lies on the mono plane (C's NDC depth z), monoplane's one change (docs/rig.md).
glm::dvec2 mono_size_for_eye(const RigInputs& in, double m, int eye, const Cameras& c, double z) {
    if (in.cant[eye] != 0.0) {
        // Projective: the eye's pixels per unit of C vary over the plane, and much: a plane
        // camera's tangent-space pixels shrink in angle towards its wide edges, which a turned
        // eye's field reaches (at 15 degrees of cant the Vive's eye needs 1.0 to 4.6 of its
        // pixels per C pixel from one edge to the other). Eq. 8's rule, C's pixels nowhere
        // smaller than the eye's, would then blur most of the far field, and its opposite would
        // make C several times an eye's size. C instead matches the eye on the eye's own axis,
        // where acuity and lens sharpness peak (docs/hybrid.md: finer towards one edge, coarser
        // towards the other).
        const glm::dvec3 axis = ray_in_head(in, eye, 0.0, 0.0);
        const glm::dvec3 on_plane = c.eye_positions[eye] + axis * (m / -axis.z);
        const glm::dvec4 mono_clip =
            c.mono_projection * glm::dvec4(on_plane - c.mono_position, 1.0);
        const glm::dvec2 ndc = glm::dvec2(mono_clip) / mono_clip.w;
        return 2.0 * eye_pixels_per_mono_ndc(in, c.mono_to_eye[eye], ndc.x, ndc.y, z);
    }
    auto to_eye_ndc = [&](double x, double y) {
        const glm::dvec4 clip = c.mono_to_eye[eye] * glm::dvec4(x, y, z, 1.0);
        return glm::dvec2(clip) / clip.w;  // the dehomogenisation the paper notes under eq. 8
    };
    const glm::dvec2 q00 = to_eye_ndc(-1.0, -1.0);
    const glm::dvec2 q10 = to_eye_ndc(+1.0, -1.0);
    const glm::dvec2 q01 = to_eye_ndc(-1.0, +1.0);
    return {0.5 * (q10.x - q00.x) * in.eye_width,
            0.5 * (q01.y - q00.y) * in.eye_height};  // Vulkan y down: positive
}

Cameras compute_cameras_with_overlap(const RigInputs& in, double m, double overlap) {
    Cameras c;
    c.s = offset_behind_eyes(in);
    const double s = c.s;
    c.eye_positions = {glm::dvec3(eye_x(in, kLeft), 0.0, 0.0),
                       glm::dvec3(eye_x(in, kRight), 0.0, 0.0)};
    c.mono_position = glm::dvec3(0.0, 0.0, s);
    c.mono_tangents = mono_frustum(in, m, s);

    // eq. 3 and eq. 4: C renders from eps in front of the mono plane to the far plane; the paper's
    // n_C = m - s_C - eps with s_C = z_C = -s is C's own distance, as here.
    c.overlap = overlap;
    c.mono_near = m - c.overlap + s;
    c.mono_far = in.far + s;
    c.mono_projection = projection_reversed_z(c.mono_tangents, c.mono_near, c.mono_far);
    for (int eye : {kLeft, kRight}) map_mono_to_eye(in, m, eye, c);

    // eq. 6-8: only on the mono plane does a point of C's image land where the eye sees it, so
    // only there do the pixel footprints of C and the eye meet (Sect. 4.2: "resolution should
    // match at the transition").
    const glm::dvec4 plane_clip = c.mono_projection * glm::dvec4(0.0, 0.0, -(m + s), 1.0);
    c.mono_plane_ndc_depth = plane_clip.z / plane_clip.w;
    c.mono_size = glm::dvec2(kInfinity);
    for (int eye : {kLeft, kRight}) {
        c.mono_size =
            glm::min(c.mono_size, mono_size_for_eye(in, m, eye, c, c.mono_plane_ndc_depth));
    }
    return c;
}

// The overlap eps: the paper's k s m (eq. 3), or more where C's pixels are coarse. Near the
// plane, the C texel an eye pixel reads sees its surface along a ray up to one texel, tau (m + s)
// on the plane, beside the eye's. On a surface at angle theta to the rays that moves the hit by
// tau (m + s) / tan(theta) in depth: if that exceeds eps, C's near plane has cut the surface
// there and the eye shows what lies behind it (the cutting line on grazing surfaces,
// docs/hybrid.md). eps therefore covers surfaces down to RigInputs::grazing_angle. It is capped
// where C's extra near content would show beside near silhouettes: the eye and C rays through
// one plane point part by (d/2) eps / m at m - eps, seen from there as
// (d/2) eps / (m (m - eps)), which the cap keeps within one eye pixel (alpha_e): eps <=
// alpha_e m^2 / (d/2 + alpha_e m). k = 0 means no overlap at all.
double overlap_for(const RigInputs& in, double m, double s, const Cameras& provisional) {
    if (in.overlap_k == 0.0) return 0.0;
    const double paper = in.overlap_k * s * m;
    if (!(in.grazing_angle > 0.0) || s == 0.0) return paper;
    const Tangents& ct = provisional.mono_tangents;
    const double texel = std::max((ct.right - ct.left) / provisional.mono_size.x,
                                  (ct.up - ct.down) / provisional.mono_size.y);
    const double footprint = texel * (m + s) / std::tan(in.grazing_angle);
    double eye_pixel = kInfinity;
    for (int eye : {kLeft, kRight}) {
        const Tangents& t = in.eyes[eye];
        eye_pixel = std::min(
            {eye_pixel, (t.right - t.left) / in.eye_width, (t.up - t.down) / in.eye_height});
    }
    const double half_ipd = 0.5 * in.ipd;
    const double ghost_cap = eye_pixel * m * m / (half_ipd + eye_pixel * m);
    return std::max(paper, std::min(footprint, ghost_cap));
}

Cameras compute_cameras(const RigInputs& in, double m) {
    const double s = offset_behind_eyes(in);
    const Cameras provisional = compute_cameras_with_overlap(in, m, in.overlap_k * s * m);
    const double overlap = overlap_for(in, m, s, provisional);
    if (overlap == provisional.overlap) return provisional;
    return compute_cameras_with_overlap(in, m, overlap);
}

// w_C of eq. 8 in closed form: the width of the union of the eyes' cross-sections at distance
// m, in the pixel pitch of the coarser eye. Used for the limit m -> f of the allocation.
double mono_width_closed_form(const RigInputs& in, double m) {
    double union_left = kInfinity;
    double union_right = -kInfinity;
    double widest_field = 0.0;
    for (int eye : {kLeft, kRight}) {
        union_left = std::min(union_left, eye_x(in, eye) + in.eyes[eye].left * m);
        union_right = std::max(union_right, eye_x(in, eye) + in.eyes[eye].right * m);
        widest_field = std::max(widest_field, in.eyes[eye].right - in.eyes[eye].left);
    }
    return (union_right - union_left) / m * in.eye_width / widest_field;
}

// ceil, forgiving rounding noise of a few ulps: a w_C that is 1344 in exact arithmetic but
// 1344.0000000002 after the matrix products must allocate 1344 pixels, not 1345.
int ceil_pixels(double size) {
    return static_cast<int>(std::ceil(size - 1e-9 * std::max(1.0, size)));
}

// W_C, H_C (Sect. 4.2): C's image is allocated once for the nearest selectable m. h_C does not
// depend on m. For parallel eyes w_C is, as a function of 1/m, a convex function (a max of two
// lines minus a min of two), so over every selectable m in [nearest, f) it peaks at one of the
// two ends. For a normal headset (each outer edge belongs to the outer eye) that is the nearest m,
// as the paper says; for strongly asymmetric frusta it can be the far end, which the second term
// covers, so the uv sub-range never exceeds [0, 1]^2. Canted eyes have no closed form: the
// largest size over 64 values of m evenly spaced in 1/m from the nearest to just before f, and
// never less than this m's own (a selectable m between the samples may still need more; the
// renderer then grows C's image, as for any m below the allocation's).
glm::ivec2 mono_allocation(const RigInputs& inputs, const Cameras& cameras) {
    const double m = inputs.mono_plane;
    const double nearest = inputs.nearest_mono_plane > 0.0 ? inputs.nearest_mono_plane : m;
    const glm::dvec2 nearest_size =
        nearest == m ? cameras.mono_size : compute_cameras(inputs, nearest).mono_size;
    if (!is_canted(inputs)) {
        return {ceil_pixels(std::max(nearest_size.x, mono_width_closed_form(inputs, inputs.far))),
                ceil_pixels(nearest_size.y)};
    }
    glm::dvec2 largest = glm::max(nearest_size, cameras.mono_size);
    for (int i = 1; i < 64; ++i) {
        const double inverse = 1.0 / nearest + (1.0 / inputs.far - 1.0 / nearest) * i / 64.0;
        largest = glm::max(largest, compute_cameras(inputs, 1.0 / inverse).mono_size);
    }
    return {ceil_pixels(largest.x), ceil_pixels(largest.y)};
}

// The offsets of the Fig. 2 error at one depth: growth = (z - m) / (z + s), 1 in the limit.
PixelError error_with_growth(const Rig& rig, double growth) {
    const RigInputs& in = rig.inputs;
    const double s = rig.mono.offset_behind_eyes;
    const double m = in.mono_plane;
    PixelError worst;
    for (int eye : {kLeft, kRight}) {
        const Tangents& t = in.eyes[eye];
        const double x = eye_x(in, eye);
        // Horizontal tangent offset (z - m)(t s - x_e) / (m (z + s)) is linear in t: its largest
        // magnitude over the field is at an edge (the inner edge for a normal headset).
        const double horizontal_tangent =
            std::max(std::abs(t.left * s - x), std::abs(t.right * s - x)) * growth / m;
        // Vertical: t_y s (z - m) / (m (z + s)), largest at the top or bottom edge.
        const double vertical_tangent = std::max(-t.down, t.up) * s * growth / m;
        const double horizontal_px = horizontal_tangent * in.eye_width / (t.right - t.left);
        const double vertical_px = vertical_tangent * in.eye_height / (t.up - t.down);
        worst.horizontal_px = std::max(worst.horizontal_px, horizontal_px);
        worst.vertical_px = std::max(worst.vertical_px, vertical_px);
        // Both maxima are reached at the same corner, so the Euclidean maximum is their hypot.
        worst.euclidean_px = std::max(worst.euclidean_px, std::hypot(horizontal_px, vertical_px));
    }
    return worst;
}

// The Fig. 2 offsets for canted eyes, where no closed form is at hand: for each direction
// (tan_x, tan_y) of a 65 x 65 grid over each eye's field, the point at `depth` in front of the
// eyes' plane along it (or its direction, at infinity), its central projection from C onto the
// plane (what hybrid shows), and that point's pixel against the direction's own pixel.
PixelError canted_error_at_depth(const Rig& rig, double depth) {
    const RigInputs& in = rig.inputs;
    const double m = in.mono_plane;
    const glm::dvec3 c = rig.mono_position;
    constexpr int kSamples = 65;
    PixelError worst;
    for (int eye : {kLeft, kRight}) {
        const Tangents& t = in.eyes[eye];
        const glm::dvec3 e = rig.eye_positions[eye];
        for (int i = 0; i < kSamples; ++i) {
            for (int j = 0; j < kSamples; ++j) {
                const double tan_x = t.left + (t.right - t.left) * i / (kSamples - 1);
                const double tan_y = t.down + (t.up - t.down) * j / (kSamples - 1);
                const glm::dvec3 r = ray_in_head(in, eye, tan_x, tan_y);
                glm::dvec3 on_plane;
                if (std::isinf(depth)) {
                    on_plane = c + r * ((m + c.z) / -r.z);
                } else {
                    const glm::dvec3 point = e + r * (depth / -r.z);
                    on_plane = c + (point - c) * ((m + c.z) / (c.z - point.z));
                }
                const glm::dvec2 shown = eye_pixel_stereo(rig, eye, on_plane);
                const glm::dvec2 true_pixel((tan_x - t.left) / (t.right - t.left) * in.eye_width,
                                            (t.up - tan_y) / (t.up - t.down) * in.eye_height);
                const glm::dvec2 offset = glm::abs(shown - true_pixel);
                worst.horizontal_px = std::max(worst.horizontal_px, offset.x);
                worst.vertical_px = std::max(worst.vertical_px, offset.y);
                worst.euclidean_px = std::max(worst.euclidean_px, glm::length(offset));
            }
        }
    }
    return worst;
}

}  // namespace

bool is_canted(const RigInputs& inputs) {
    return inputs.cant[kLeft] != 0.0 || inputs.cant[kRight] != 0.0;
}

glm::dmat3 eye_rotation(const RigInputs& inputs, int eye) {
    MONOPLANE_EXPECTS(eye == kLeft || eye == kRight);
    const double a = inputs.cant[eye];
    if (a == 0.0) return glm::dmat3(1.0);
    // Ry(a), column-major: +a turns -z towards -x (left).
    const double c = std::cos(a);
    const double s = std::sin(a);
    return glm::dmat3(glm::dvec3(c, 0.0, -s), glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(s, 0.0, c));
}

Result<Rig> build_rig(const RigInputs& inputs) {
    if (std::optional<Error> problem = validate(inputs)) return *problem;

    Rig rig;
    rig.inputs = inputs;
    const double m = inputs.mono_plane;

    if (m >= inputs.far) {
        // Nothing lies beyond the plane: hybrid equals stereo, C is not rendered.
        rig.mono_skipped = true;
        rig.mono = MonoCamera{};
        rig.mono.uv_scale = glm::dvec2(0.0);
        rig.eye_positions = {glm::dvec3(eye_x(inputs, kLeft), 0.0, 0.0),
                             glm::dvec3(eye_x(inputs, kRight), 0.0, 0.0)};
        for (int eye : {kLeft, kRight}) {
            rig.eye_from_head[eye] = eye_from_head_matrix(inputs, eye);
            rig.eye_projection[eye] =
                projection_reversed_z(inputs.eyes[eye], inputs.near, inputs.far);
            rig.mono_to_eye[eye] = glm::dmat4(1.0);
            rig.eye_to_mono[eye] = glm::dmat4(1.0);
        }
        return rig;
    }

    const Cameras cameras = compute_cameras(inputs, m);
    rig.overlap = cameras.overlap;
    rig.eye_positions = cameras.eye_positions;
    rig.mono_position = cameras.mono_position;
    for (int eye : {kLeft, kRight}) rig.eye_from_head[eye] = eye_from_head_matrix(inputs, eye);
    rig.eye_projection = cameras.eye_projection;
    rig.mono_projection = cameras.mono_projection;
    rig.mono_to_eye = cameras.mono_to_eye;
    rig.eye_to_mono = cameras.eye_to_mono;

    MonoCamera& mono = rig.mono;
    mono.offset_behind_eyes = cameras.s;
    mono.tangents = cameras.mono_tangents;
    mono.near = cameras.mono_near;
    mono.far = cameras.mono_far;
    mono.mono_plane_ndc_depth = cameras.mono_plane_ndc_depth;
    mono.width = cameras.mono_size.x;
    mono.height = cameras.mono_size.y;
    mono.viewport_width = ceil_pixels(mono.width);
    mono.viewport_height = ceil_pixels(mono.height);

    const glm::ivec2 allocation = mono_allocation(inputs, cameras);
    mono.allocated_width = allocation.x;
    mono.allocated_height = allocation.y;
    mono.uv_scale = glm::dvec2(mono.viewport_width, mono.viewport_height) /
                    glm::dvec2(mono.allocated_width, mono.allocated_height);

    const PixelError limit =
        is_canted(inputs) ? canted_error_at_depth(rig, kInfinity) : error_with_growth(rig, 1.0);
    rig.max_error_px = limit.horizontal_px;
    rig.max_error_px_2d = limit.euclidean_px;
    return rig;
}

PixelError error_at_depth(const Rig& rig, double depth) {
    MONOPLANE_EXPECTS(!std::isnan(depth));
    const double m = rig.inputs.mono_plane;
    if (rig.mono_skipped || !(depth > m)) return {};
    if (is_canted(rig.inputs)) return canted_error_at_depth(rig, depth);
    const double s = rig.mono.offset_behind_eyes;
    const double growth = std::isinf(depth) ? 1.0 : (depth - m) / (depth + s);
    return error_with_growth(rig, growth);
}

glm::dvec2 eye_pixel_stereo(const Rig& rig, int eye, const glm::dvec3& point) {
    MONOPLANE_EXPECTS(eye == kLeft || eye == kRight);
    const glm::dvec3 view =
        glm::transpose(eye_rotation(rig.inputs, eye)) * (point - rig.eye_positions[eye]);
    MONOPLANE_EXPECTS(view.z < 0.0);
    const Tangents& t = rig.inputs.eyes[eye];
    const double tan_x = view.x / -view.z;
    const double tan_y = view.y / -view.z;
    return {(tan_x - t.left) / (t.right - t.left) * rig.inputs.eye_width,
            (t.up - tan_y) / (t.up - t.down) * rig.inputs.eye_height};
}

glm::dvec2 eye_pixel_hybrid(const Rig& rig, int eye, const glm::dvec3& point) {
    if (rig.mono_skipped) return eye_pixel_stereo(rig, eye, point);
    // Central projection from C onto the mono plane z = -m (Fig. 2, centre right: p -> p_C).
    const glm::dvec3 c = rig.mono_position;
    const double distance_from_mono = c.z - point.z;
    MONOPLANE_EXPECTS(distance_from_mono > 0.0);
    const double to_plane = (rig.inputs.mono_plane + c.z) / distance_from_mono;
    const glm::dvec3 on_plane = c + (point - c) * to_plane;
    return eye_pixel_stereo(rig, eye, on_plane);
}

glm::dmat3 mono_pixel_to_eye_pixel(const Rig& rig, int eye) {
    MONOPLANE_EXPECTS(eye == kLeft || eye == kRight);
    if (rig.mono_skipped) return glm::dmat3(1.0);
    const double w_c = rig.mono.viewport_width;
    const double h_c = rig.mono.viewport_height;
    const double z_plane = rig.mono.mono_plane_ndc_depth;
    // C's pixel (x, y, 1) -> C's clip coordinates of its point on the plane: (2x/w - 1,
    // 2y/h - 1, z_plane, 1), a 4 x 3 matrix (glm: 3 columns of 4 rows).
    glm::dmat3x4 pixel_to_mono_clip(0.0);
    pixel_to_mono_clip[0] = glm::dvec4(2.0 / w_c, 0.0, 0.0, 0.0);
    pixel_to_mono_clip[1] = glm::dvec4(0.0, 2.0 / h_c, 0.0, 0.0);
    pixel_to_mono_clip[2] = glm::dvec4(-1.0, -1.0, z_plane, 1.0);
    // Eye clip (X, Y, Z, W) -> homogeneous eye pixel ((X/W + 1) w_e / 2, (Y/W + 1) h_e / 2): a
    // 3 x 4 matrix (4 columns of 3 rows).
    const double w_e = rig.inputs.eye_width;
    const double h_e = rig.inputs.eye_height;
    glm::dmat4x3 eye_clip_to_pixel(0.0);
    eye_clip_to_pixel[0] = glm::dvec3(w_e / 2.0, 0.0, 0.0);
    eye_clip_to_pixel[1] = glm::dvec3(0.0, h_e / 2.0, 0.0);
    eye_clip_to_pixel[3] = glm::dvec3(w_e / 2.0, h_e / 2.0, 1.0);
    return eye_clip_to_pixel * rig.mono_to_eye[eye] * pixel_to_mono_clip;
}

glm::dvec2 mono_velocity_to_eye(const Rig& rig, int eye) {
    MONOPLANE_EXPECTS(eye == kLeft || eye == kRight);
    if (rig.mono_skipped) return glm::dvec2(1.0);
    const double z = rig.mono.mono_plane_ndc_depth;
    auto mapped = [&](double x, double y) {
        const glm::dvec4 q = rig.mono_to_eye[eye] * glm::dvec4(x, y, z, 1.0);
        return glm::dvec2(q) / q.w;
    };
    const glm::dvec2 q00 = mapped(-1.0, -1.0);
    const glm::dvec2 q10 = mapped(1.0, -1.0);
    const glm::dvec2 q01 = mapped(-1.0, 1.0);
    return 0.5 * glm::dvec2(q10.x - q00.x, q01.y - q00.y);
}

double nearest_eye_depth_of_plane(const Rig& rig, double distance) {
    if (rig.mono_skipped) return 0.0;
    double nearest = -kInfinity;
    for (int eye : {kLeft, kRight}) {
        // On a plane, an eye's view depth is affine, so over the convex cross-section its least
        // distance (largest reversed-Z depth) is at a corner.
        for (const glm::dvec3& r : corner_rays(rig.inputs, eye)) {
            const glm::dvec3 point = rig.eye_positions[eye] + r * (distance / -r.z);
            const glm::dvec4 clip =
                rig.eye_projection[eye] * rig.eye_from_head[eye] * glm::dvec4(point, 1.0);
            nearest = std::max(nearest, clip.z / clip.w);
        }
    }
    return nearest;
}

}  // namespace monoplane::rig
