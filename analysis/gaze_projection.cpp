#include "analysis/gaze_projection.h"

#include <array>
#include <cmath>

namespace monoplane::analysis {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// v rotated by the unit quaternion (w, x, y, z), normalised here: the log stores floats.
Vec3 rotated(const std::array<double, 7>& head, const Vec3& v) {
    const double norm =
        std::sqrt(head[3] * head[3] + head[4] * head[4] + head[5] * head[5] + head[6] * head[6]);
    if (!(norm > 0.0)) return v;
    const double w = head[3] / norm;
    const Vec3 q{head[4] / norm, head[5] / norm, head[6] / norm};
    // v + 2w (q x v) + 2 q x (q x v)
    const Vec3 t = cross(q, v);
    const Vec3 u = cross(q, t);
    return {v[0] + 2.0 * (w * t[0] + u[0]), v[1] + 2.0 * (w * t[1] + u[1]),
            v[2] + 2.0 * (w * t[2] + u[2])};
}

// From the seat's frame into the left eye's: undo the cant (a yaw by `cant` about +y).
Vec3 into_eye_frame(const Vec3& v, double cant) {
    const double c = std::cos(cant);
    const double s = std::sin(cant);
    return {c * v[0] - s * v[2], v[1], s * v[0] + c * v[2]};
}

}  // namespace

std::optional<EyeImagePoint> project_into_left_eye(const GazeSampleRow& sample,
                                                   const SeatEye& eye) {
    const Vec3& d = sample.direction;
    Vec3 from_eye;  // the gaze point relative to the left eye, or its direction for the sky
    if (sample.depth_m) {
        // depth_m is measured along the head's -z, so the ray reaches it after depth / -d.z.
        if (!(d[2] < 0.0)) return std::nullopt;
        const double along = *sample.depth_m / -d[2];
        const Vec3 offset = rotated(sample.head, {d[0] * along, d[1] * along, d[2] * along});
        from_eye = {sample.head[0] + offset[0] + eye.ipd / 2.0, sample.head[1] + offset[1],
                    sample.head[2] + offset[2]};
    } else {
        from_eye = rotated(sample.head, d);  // at infinity: the eye's offset does not matter
    }
    const Vec3 v = into_eye_frame(from_eye, eye.cant);
    if (!(v[2] < 0.0)) return std::nullopt;
    EyeImagePoint p;
    p.tan_x = v[0] / -v[2];
    p.tan_y = v[1] / -v[2];
    p.u = (p.tan_x - eye.tan_left) / (eye.tan_right - eye.tan_left);
    p.v = (eye.tan_up - p.tan_y) / (eye.tan_up - eye.tan_down);
    return p;
}

}  // namespace monoplane::analysis
