#include "rig/angular_error.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>

#include "common/programming_error.h"

namespace monoplane::rig {
namespace {

// The largest value of f over the box [u0, u1] x [v0, v1] where f is defined (f returns nothing
// outside the region searched): the best of a samples_u x samples_v grid (edges included),
// refined by a compass search whose step halves until it is 1e-12 of the box.
struct Box {
    double u0, u1, v0, v1;
};
using Objective = std::function<std::optional<double>(double u, double v)>;
double maximize(const Objective& f, const Box& box, int samples_u, int samples_v) {
    double best = -kInfinity;
    double best_u = box.u0, best_v = box.v0;
    for (int i = 0; i < samples_u; ++i) {
        for (int j = 0; j < samples_v; ++j) {
            const double u =
                samples_u > 1 ? box.u0 + (box.u1 - box.u0) * i / (samples_u - 1) : box.u0;
            const double v =
                samples_v > 1 ? box.v0 + (box.v1 - box.v0) * j / (samples_v - 1) : box.v0;
            const std::optional<double> value = f(u, v);
            if (value && *value > best) {
                best = *value;
                best_u = u;
                best_v = v;
            }
        }
    }
    if (best == -kInfinity) return 0.0;  // nothing of the region lies in the box
    double step_u = samples_u > 1 ? (box.u1 - box.u0) / (samples_u - 1) : 0.0;
    double step_v = samples_v > 1 ? (box.v1 - box.v0) / (samples_v - 1) : 0.0;
    const double tolerance = 1e-12 * std::max(box.u1 - box.u0, box.v1 - box.v0);
    while (std::max(step_u, step_v) > tolerance) {
        bool moved = false;
        for (const auto& [du, dv] : {std::pair{step_u, 0.0}, std::pair{-step_u, 0.0},
                                     std::pair{0.0, step_v}, std::pair{0.0, -step_v}}) {
            const double u = std::clamp(best_u + du, box.u0, box.u1);
            const double v = std::clamp(best_v + dv, box.v0, box.v1);
            const std::optional<double> value = f(u, v);
            if (value && *value > best) {
                best = *value;
                best_u = u;
                best_v = v;
                moved = true;
            }
        }
        if (!moved) {
            step_u *= 0.5;
            step_v *= 0.5;
        }
    }
    return best;
}

// Where hybrid shows `point` (head frame): its central projection from C onto the plane z = -m.
glm::dvec3 on_mono_plane(const Rig& rig, const glm::dvec3& point) {
    const glm::dvec3 c = rig.mono_position;
    return c + (point - c) * ((rig.inputs.mono_plane + c.z) / (c.z - point.z));
}
// The same for a direction at infinity.
glm::dvec3 direction_on_mono_plane(const Rig& rig, const glm::dvec3& direction) {
    const glm::dvec3 c = rig.mono_position;
    return c + direction * ((rig.inputs.mono_plane + c.z) / -direction.z);
}

// Eye e's own tangents of a head-frame point in front of it.
glm::dvec2 eye_tangents(const Rig& rig, int eye, const glm::dvec3& point) {
    const glm::dvec3 view =
        glm::transpose(eye_rotation(rig.inputs, eye)) * (point - rig.eye_positions[eye]);
    return {view.x / -view.z, view.y / -view.z};
}

bool in_field(const Tangents& t, const glm::dvec2& tangents) {
    constexpr double kSlack = 1e-12;
    return tangents.x >= t.left - kSlack && tangents.x <= t.right + kSlack &&
           tangents.y >= t.down - kSlack && tangents.y <= t.up + kSlack;
}

// Parallel eye: max over t in [t0, t1] of |atan(a t + b) - atan(t)|, at an end or a root of
// (a - a^2) t^2 - 2 a b t + (a - 1 - b^2) = 0 (where the derivative a / (1 + (a t + b)^2) -
// 1 / (1 + t^2) vanishes).
double parallel_eye_error(double a, double b, double t0, double t1) {
    auto error = [&](double t) { return std::abs(std::atan(a * t + b) - std::atan(t)); };
    double worst = std::max(error(t0), error(t1));
    const double qa = a - a * a, qb = -2.0 * a * b, qc = a - 1.0 - b * b;
    std::vector<double> roots;
    if (std::abs(qa) < 1e-300) {
        if (std::abs(qb) > 0.0) roots.push_back(-qc / qb);
    } else {
        const double discriminant = qb * qb - 4.0 * qa * qc;
        if (discriminant >= 0.0) {
            // The numerically stable pair (no cancellation between -qb and the root).
            const double q = -0.5 * (qb + std::copysign(std::sqrt(discriminant), qb));
            if (q != 0.0) roots.push_back(q / qa);
            if (q != 0.0) roots.push_back(qc / q);
        }
    }
    for (const double t : roots) {
        if (t > t0 && t < t1) worst = std::max(worst, error(t));
    }
    return worst;
}

double eye_error(const Rig& rig, int eye, double depth) {
    const RigInputs& in = rig.inputs;
    const Tangents& t = in.eyes[eye];
    if (!is_canted(in)) {
        const double s = rig.mono.offset_behind_eyes;
        const double m = in.mono_plane;
        const double x = rig.eye_positions[eye].x;
        const double a = std::isinf(depth) ? 1.0 + s / m : depth * (m + s) / (m * (depth + s));
        const double b = std::isinf(depth) ? -x / m : x * (m - depth) / (m * (depth + s));
        return parallel_eye_error(a, b, t.left, t.right);
    }
    const glm::dvec3 e = rig.eye_positions[eye];
    const Objective error = [&](double tan_x, double tan_y) -> std::optional<double> {
        const glm::dvec3 ray = eye_rotation(in, eye) * glm::dvec3(tan_x, tan_y, -1.0);
        if (ray.z >= 0.0) return std::nullopt;
        const glm::dvec3 shown = std::isinf(depth) ? direction_on_mono_plane(rig, ray)
                                                   : on_mono_plane(rig, e + ray * (depth / -ray.z));
        return std::abs(std::atan(eye_tangents(rig, eye, shown).x) - std::atan(tan_x));
    };
    return maximize(error, {t.left, t.right, t.down, t.up}, 33, 33);
}

// The change of horizontal disparity of the point in head-frame direction (u, v, -1) at `depth`
// (or at infinity), if both eyes see it. Horizontal angles are the head frame's, so that the
// eyes' angles of a point are comparable also for canted eyes.
std::optional<double> disparity_change(const Rig& rig, double depth, double u, double v) {
    const glm::dvec3 direction(u, v, -1.0);
    const glm::dvec3 point = std::isinf(depth) ? direction : direction * depth;
    const glm::dvec3 shown =
        std::isinf(depth) ? direction_on_mono_plane(rig, direction) : on_mono_plane(rig, point);
    double change = 0.0;
    for (int eye : {kLeft, kRight}) {
        const glm::dvec3 e = rig.eye_positions[eye];
        // Seen from the eye: the point, or at infinity the direction itself.
        const glm::dvec3 seen = std::isinf(depth) ? direction : point - e;
        const glm::dvec3 in_eye = glm::transpose(eye_rotation(rig.inputs, eye)) * seen;
        if (in_eye.z >= 0.0 ||
            !in_field(rig.inputs.eyes[eye], glm::dvec2(in_eye.x, in_eye.y) / -in_eye.z)) {
            return std::nullopt;
        }
        const double true_angle = std::atan2(seen.x, -seen.z);
        const glm::dvec3 to_shown = shown - e;
        const double shown_angle = std::atan2(to_shown.x, -to_shown.z);
        change += (eye == kLeft ? 1.0 : -1.0) * (shown_angle - true_angle);
    }
    return std::abs(change);
}

double disparity_error(const Rig& rig, double depth) {
    // The head-frame tangents both eyes' fields could reach: the union of their bounds.
    Box box{kInfinity, -kInfinity, kInfinity, -kInfinity};
    for (int eye : {kLeft, kRight}) {
        const Tangents& t = rig.inputs.eyes[eye];
        for (const double tx : {t.left, t.right}) {
            for (const double ty : {t.down, t.up}) {
                const glm::dvec3 r = eye_rotation(rig.inputs, eye) * glm::dvec3(tx, ty, -1.0);
                box.u0 = std::min(box.u0, r.x / -r.z);
                box.u1 = std::max(box.u1, r.x / -r.z);
                box.v0 = std::min(box.v0, r.y / -r.z);
                box.v1 = std::max(box.v1, r.y / -r.z);
            }
        }
    }
    const Objective change = [&](double u, double v) { return disparity_change(rig, depth, u, v); };
    if (!is_canted(rig.inputs)) {
        // The change does not depend on v: search along the horizon of both fields.
        const double v = std::clamp(0.0, box.v0, box.v1);
        return maximize(change, {box.u0, box.u1, v, v}, 513, 1);
    }
    return maximize(change, box, 65, 33);
}

}  // namespace

AngularError angular_error_at_depth(const Rig& rig, double depth) {
    MONOPLANE_EXPECTS(!std::isnan(depth));
    if (rig.mono_skipped || !(depth > rig.inputs.mono_plane)) return {};
    AngularError error;
    for (int eye : {kLeft, kRight}) {
        error.eye_arcmin =
            std::max(error.eye_arcmin, eye_error(rig, eye, depth) * kArcminPerRadian);
    }
    error.disparity_arcmin = disparity_error(rig, depth) * kArcminPerRadian;
    return error;
}

AngularError max_angular_error(const Rig& rig) {
    return angular_error_at_depth(rig, kInfinity);
}

namespace {

// The angle between two directions, robust at small angles (atan2 of |a x b| and a . b).
double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace

PointAngularError angular_error_at_point(const Rig& rig, const glm::dvec3& point) {
    PointAngularError error;
    if (rig.mono_skipped || -point.z <= rig.inputs.mono_plane) return error;
    const glm::dvec3 shown = on_mono_plane(rig, point);
    for (int e = 0; e < 2; ++e) {
        const glm::dvec3& eye = rig.eye_positions[static_cast<std::size_t>(e)];
        error.eye_arcmin[static_cast<std::size_t>(e)] =
            angle_between(point - eye, shown - eye) * kArcminPerRadian;
    }
    return error;
}

PointAngularError angular_error_in_direction(const Rig& rig, const glm::dvec3& direction) {
    MONOPLANE_EXPECTS(direction.z < 0.0);
    PointAngularError error;
    if (rig.mono_skipped) return error;
    // C's ray towards the point is parallel to every eye's: it lies infinitely far.
    const glm::dvec3 shown = direction_on_mono_plane(rig, direction);
    for (int e = 0; e < 2; ++e) {
        const glm::dvec3& eye = rig.eye_positions[static_cast<std::size_t>(e)];
        error.eye_arcmin[static_cast<std::size_t>(e)] =
            angle_between(direction, shown - eye) * kArcminPerRadian;
    }
    return error;
}

}  // namespace monoplane::rig
