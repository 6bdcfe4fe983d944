// The triple-frustum rig of Fink et al. 2019 (papers/000, Sect. 3, 4.1, 4.2); docs/rig.md maps
// every equation to the names used here. All distances are metres, all tangents XrFovf-style.
#include "renderer/rig/rig.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include <glm/ext/matrix_double3x4.hpp>
#include <glm/ext/matrix_double4x3.hpp>
#include <glm/ext/matrix_transform.hpp>

#include "renderer/rig/projection.h"

namespace monoplane::rig {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

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

// s: the outer frustum planes of the eyes cross the z axis behind the eyes (eq. 1, z_C = -s).
// The left eye's outer plane x = -d/2 + tan_left(L) dist meets x = 0 at dist = d / (2 tan_left(L))
// (negative: behind the eyes), the right's at -d / (2 tan_right(R)); C takes the farther back, so
// that both outer planes pass in front of it and its frustum can contain both eyes' fields.
double offset_behind_eyes(const RigInputs& inputs) {
    const double left_crossing_behind = inputs.ipd / (2.0 * -inputs.eyes[kLeft].left);
    const double right_crossing_behind = inputs.ipd / (2.0 * inputs.eyes[kRight].right);
    return std::max(left_crossing_behind, right_crossing_behind);
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
    };
    for (const auto& [name, value] : scalars) {
        if (!std::isfinite(value)) return problem(std::string(name) + " is not a finite number");
    }
    for (int eye : {kLeft, kRight}) {
        const Tangents& t = in.eyes[eye];
        const std::pair<const char*, double> sides[] = {
            {"tan_left", t.left}, {"tan_right", t.right}, {"tan_down", t.down}, {"tan_up", t.up}};
        for (const auto& [side, value] : sides) {
            const std::string name = std::string("eyes[") + eye_name(eye) + "]." + side;
            if (!std::isfinite(value)) return problem(name + " is not a finite number");
            if (std::abs(value) > kMaxTangent) {
                return problem(name + " = " + number(value) + " exceeds the sane bound of " +
                               number(kMaxTangent) + " (84 degrees from the view axis)");
            }
        }
        const std::string prefix = std::string("eyes[") + eye_name(eye) + "].";
        if (!(t.left < 0.0)) {
            return problem(prefix + "tan_left = " + number(t.left) +
                           " must be negative (XrFovf convention: left of the view axis)");
        }
        if (!(t.right > 0.0)) {
            return problem(prefix + "tan_right = " + number(t.right) + " must be positive");
        }
        if (!(t.down < 0.0)) {
            return problem(prefix + "tan_down = " + number(t.down) +
                           " must be negative (XrFovf convention: +y is up)");
        }
        if (!(t.up > 0.0)) {
            return problem(prefix + "tan_up = " + number(t.up) + " must be positive");
        }
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

// The exact inverse of projection_reversed_z (renderer/rig/projection.cpp), written out rather
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

Cameras compute_cameras(const RigInputs& in, double m) {
    Cameras c;
    c.s = offset_behind_eyes(in);
    const double s = c.s;
    c.eye_positions = {glm::dvec3(eye_x(in, kLeft), 0.0, 0.0),
                       glm::dvec3(eye_x(in, kRight), 0.0, 0.0)};
    c.mono_position = glm::dvec3(0.0, 0.0, s);

    // C's frustum (eq. 2, geometric meaning per DESIGN.md 3): the slopes from C, at distance
    // m + s from the mono plane, to the outermost edges of the eyes' cross-sections with the plane.
    // Vertically x_eye plays no part, so C's vertical tangents shrink by m / (m + s).
    const double from_mono = m + s;
    Tangents& ct = c.mono_tangents;
    ct.left = ct.right = ct.down = ct.up = 0.0;
    for (int eye : {kLeft, kRight}) {
        const Tangents& t = in.eyes[eye];
        const double x = eye_x(in, eye);
        const double left = (x + t.left * m) / from_mono;
        const double right = (x + t.right * m) / from_mono;
        const double down = t.down * m / from_mono;
        const double up = t.up * m / from_mono;
        if (eye == kLeft) {
            ct = {left, right, down, up};
        } else {
            ct.left = std::min(ct.left, left);
            ct.right = std::max(ct.right, right);
            ct.down = std::min(ct.down, down);
            ct.up = std::max(ct.up, up);
        }
    }

    // eq. 3 and eq. 4: C renders from eps in front of the mono plane to the far plane; the paper's
    // n_C = m - s_C - eps with s_C = z_C = -s is C's own distance, as here.
    c.overlap = in.overlap_k * s * m;
    c.mono_near = m - c.overlap + s;
    c.mono_far = in.far + s;

    // eq. 5 in the head frame: all three cameras share the head's orientation, so V_E V_C^-1 is
    // the translation by C's position as seen from the eye (p_C - p_E), and its inverse the
    // reverse.
    c.mono_projection = projection_reversed_z(ct, c.mono_near, c.mono_far);
    const glm::dmat4 mono_projection_inverse =
        inverse_projection_reversed_z(ct, c.mono_near, c.mono_far);
    for (int eye : {kLeft, kRight}) {
        const Tangents& t = in.eyes[eye];
        c.eye_projection[eye] = projection_reversed_z(t, in.near, m);
        const glm::dmat4 eye_projection_inverse = inverse_projection_reversed_z(t, in.near, m);
        const glm::dvec3 mono_in_eye_view = c.mono_position - c.eye_positions[eye];
        c.mono_to_eye[eye] = c.eye_projection[eye] *
                             glm::translate(glm::dmat4(1.0), mono_in_eye_view) *
                             mono_projection_inverse;
        c.eye_to_mono[eye] = c.mono_projection *
                             glm::translate(glm::dmat4(1.0), -mono_in_eye_view) *
                             eye_projection_inverse;
    }

    // eq. 6-8 with monoplane's one change (docs/rig.md): the quad Q lies on the mono plane, at C's
    // NDC depth of distance m + s, not on C's near plane. Only on the mono plane does a point of
    // C's image land where the eye sees it, so only there do the pixel footprints of C and the eye
    // meet (Sect. 4.2: "resolution should match at the transition").
    const glm::dvec4 plane_clip = c.mono_projection * glm::dvec4(0.0, 0.0, -from_mono, 1.0);
    c.mono_plane_ndc_depth = plane_clip.z / plane_clip.w;
    const double z = c.mono_plane_ndc_depth;
    c.mono_size = glm::dvec2(kInfinity);
    for (int eye : {kLeft, kRight}) {
        auto to_eye_ndc = [&](double x, double y) {
            const glm::dvec4 clip = c.mono_to_eye[eye] * glm::dvec4(x, y, z, 1.0);
            return glm::dvec2(clip) / clip.w;  // the dehomogenisation the paper notes under eq. 8
        };
        const glm::dvec2 q00 = to_eye_ndc(-1.0, -1.0);
        const glm::dvec2 q10 = to_eye_ndc(+1.0, -1.0);
        const glm::dvec2 q01 = to_eye_ndc(-1.0, +1.0);
        const double width = 0.5 * (q10.x - q00.x) * in.eye_width;
        const double height = 0.5 * (q01.y - q00.y) * in.eye_height;  // Vulkan y down: positive
        c.mono_size = glm::min(c.mono_size, glm::dvec2(width, height));
    }
    return c;
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

}  // namespace

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

    // W_C, H_C (Sect. 4.2): allocated once for the nearest selectable m. h_C does not depend on
    // m. w_C is, as a function of 1/m, a convex function (a max of two lines minus a min of two),
    // so over every selectable m in [nearest, f) it peaks at one of the two ends. For a normal
    // headset (each outer edge belongs to the outer eye) that is the nearest m, as the paper says;
    // for strongly asymmetric frusta it can be the far end, which the second term covers, so the
    // uv sub-range never exceeds [0, 1]^2.
    const double nearest = inputs.nearest_mono_plane > 0.0 ? inputs.nearest_mono_plane : m;
    const glm::dvec2 nearest_size =
        nearest == m ? cameras.mono_size : compute_cameras(inputs, nearest).mono_size;
    mono.allocated_width =
        ceil_pixels(std::max(nearest_size.x, mono_width_closed_form(inputs, inputs.far)));
    mono.allocated_height = ceil_pixels(nearest_size.y);
    mono.uv_scale = glm::dvec2(mono.viewport_width, mono.viewport_height) /
                    glm::dvec2(mono.allocated_width, mono.allocated_height);

    const PixelError limit = error_with_growth(rig, 1.0);
    rig.max_error_px = limit.horizontal_px;
    rig.max_error_px_2d = limit.euclidean_px;
    return rig;
}

PixelError error_at_depth(const Rig& rig, double depth) {
    assert(!std::isnan(depth));
    const double m = rig.inputs.mono_plane;
    if (rig.mono_skipped || !(depth > m)) return {};
    const double s = rig.mono.offset_behind_eyes;
    const double growth = std::isinf(depth) ? 1.0 : (depth - m) / (depth + s);
    return error_with_growth(rig, growth);
}

glm::dvec2 eye_pixel_stereo(const Rig& rig, int eye, const glm::dvec3& point) {
    assert(eye == kLeft || eye == kRight);
    const glm::dvec3 view = point - rig.eye_positions[eye];
    assert(view.z < 0.0);
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
    assert(distance_from_mono > 0.0);
    const double to_plane = (rig.inputs.mono_plane + c.z) / distance_from_mono;
    const glm::dvec3 on_plane = c + (point - c) * to_plane;
    return eye_pixel_stereo(rig, eye, on_plane);
}

glm::dmat3 mono_pixel_to_eye_pixel(const Rig& rig, int eye) {
    assert(eye == kLeft || eye == kRight);
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
    assert(eye == kLeft || eye == kRight);
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

}  // namespace monoplane::rig
