#include "renderer/quality/stereo_inconsistency.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

#include <glm/ext/matrix_double3x3.hpp>
#include <glm/ext/vector_double2.hpp>
#include <glm/ext/vector_double4.hpp>
#include <glm/ext/vector_float3.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "renderer/quality/colormap.h"

namespace monoplane::quality {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Footprint coordinates this close to a pixel centre are snapped onto it (see the header): far
// below any sub-pixel effect that matters for E, far above the rounding of the projections.
constexpr double kSnapPx = 1e-4;

// camera_position may differ from view_proj's centre of projection by this much (metres, plus
// a relative 1e-6 for cameras far from the origin): it tolerates matrices that went through
// float, and catches swapped eyes (an IPD off) or a head position passed for an eye.
constexpr double kCentreToleranceM = 1e-3;

std::string pixel_text(std::uint32_t i, std::uint32_t j) {
    return "(" + std::to_string(i) + ", " + std::to_string(j) + ")";
}

std::string size_text(std::uint32_t width, std::uint32_t height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

bool is_finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool is_finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

bool is_sky(float depth) {
    return depth >= kSkyLinearDepth;
}

// The centre of projection of a perspective world -> clip matrix: the point with clip x, y and w
// all zero. NaN when there is none (an orthographic or degenerate matrix).
glm::dvec3 centre_of_projection(const glm::dmat4& view_proj) {
    glm::dmat3 rows(0.0);  // rows x, y, w of view_proj, columns x, y, z
    glm::dvec3 offset(0.0);
    constexpr int kRows[3] = {0, 1, 3};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) rows[c][r] = view_proj[c][kRows[r]];
        offset[r] = view_proj[3][kRows[r]];
    }
    const double det = glm::determinant(rows);
    if (!(std::isfinite(det) && det != 0.0)) return glm::dvec3(kNaN);
    return glm::inverse(rows) * -offset;
}

// The first problem with one view's data, or an empty string.
std::string check_view(const StereoAoView& view, const char* name) {
    const std::string prefix = std::string("stereo inconsistency: the ") + name + " view ";
    if (view.width == 0 || view.height == 0) {
        return prefix + "is empty (" + size_text(view.width, view.height) +
               "); pass the size the AO was rendered at";
    }
    const std::size_t pixels = std::size_t{view.width} * view.height;
    if (view.linear_depth.size() != pixels || view.ao.size() != pixels) {
        return prefix + "is " + size_text(view.width, view.height) + ", which needs " +
               std::to_string(pixels) + " depths and AO values; got " +
               std::to_string(view.linear_depth.size()) + " and " + std::to_string(view.ao.size());
    }
    if (!is_finite(view.view_proj) || !is_finite(view.camera_position)) {
        return prefix + "has a non-finite view_proj or camera_position";
    }
    const double det = glm::determinant(view.view_proj);
    if (!(std::isfinite(det) && det != 0.0) || !is_finite(glm::inverse(view.view_proj))) {
        return prefix + "has a singular view_proj; pass the projection times the view matrix";
    }
    const glm::dvec3 centre = centre_of_projection(view.view_proj);
    if (!is_finite(centre)) {
        return prefix + "has a view_proj that is not a perspective projection";
    }
    const double distance = glm::length(centre - view.camera_position);
    if (!(distance <= kCentreToleranceM + 1e-6 * glm::length(centre))) {
        return prefix + "has its camera_position " + std::to_string(distance) +
               " m away from the centre of projection of its view_proj; pass that eye's position "
               "(are the eyes swapped?)";
    }
    for (std::uint32_t j = 0; j < view.height; ++j) {
        for (std::uint32_t i = 0; i < view.width; ++i) {
            const std::size_t k = std::size_t{j} * view.width + i;
            const float depth = view.linear_depth[k];
            if (is_sky(depth)) continue;
            if (!(depth > 0.0f)) {
                return prefix + "has linear depth " + std::to_string(depth) + " at pixel " +
                       pixel_text(i, j) + "; expected metres > 0, or >= 1e29 for sky";
            }
            if (!std::isfinite(view.ao[k])) {
                return prefix + "has a non-finite AO value at pixel " + pixel_text(i, j);
            }
        }
    }
    return {};
}

std::string check_head_and_options(const StereoHead& head, const InconsistencyOptions& options) {
    if (!is_finite(head.position) || !is_finite(head.forward) ||
        !(std::abs(glm::length(head.forward) - 1.0) <= 1e-4)) {
        return "stereo inconsistency: the head needs a finite position and a unit forward vector "
               "(the direction the linear depths are measured along)";
    }
    if (!(std::isfinite(options.back_check_px) && options.back_check_px > 0.0)) {
        return "stereo inconsistency: the back-check distance must be > 0 pixels; got " +
               std::to_string(options.back_check_px);
    }
    if (!(options.normal_threshold_deg >= 0.0 && options.normal_threshold_deg <= 180.0)) {
        return "stereo inconsistency: the normal threshold must be in [0, 180] degrees; got " +
               std::to_string(options.normal_threshold_deg);
    }
    return {};
}

// One validated view with what the per-pixel work needs.
class Eye {
  public:
    Eye(const StereoAoView& view, const StereoHead& head)
        : view_(view),
          inverse_(glm::inverse(view.view_proj)),
          forward_(head.forward),
          // d of the eye's own plane: the ray parameter t runs from there.
          eye_depth_(glm::dot(view.camera_position - head.position, head.forward)) {}

    std::uint32_t width() const { return view_.width; }
    std::uint32_t height() const { return view_.height; }
    const glm::dvec3& position() const { return view_.camera_position; }
    std::size_t index(std::uint32_t i, std::uint32_t j) const {
        return std::size_t{j} * view_.width + i;
    }
    bool sky(std::uint32_t i, std::uint32_t j) const {
        return is_sky(view_.linear_depth[index(i, j)]);
    }
    float ao(std::uint32_t i, std::uint32_t j) const { return view_.ao[index(i, j)]; }

    // World point of a pixel: NaN for sky and for a depth its ray cannot reach (the ray runs
    // parallel to or away from the depth planes, or the point would lie behind the eye).
    glm::dvec3 world_point(std::uint32_t i, std::uint32_t j) const {
        const float depth = view_.linear_depth[index(i, j)];
        if (is_sky(depth)) return glm::dvec3(kNaN);
        const glm::dvec4 ndc((i + 0.5) / view_.width * 2.0 - 1.0,
                             (j + 0.5) / view_.height * 2.0 - 1.0, 0.5, 1.0);
        const glm::dvec4 on_ray = inverse_ * ndc;
        const glm::dvec3 direction = glm::dvec3(on_ray) / on_ray.w - view_.camera_position;
        const double t = (depth - eye_depth_) / glm::dot(direction, forward_);
        if (!(std::isfinite(t) && t > 0.0)) return glm::dvec3(kNaN);
        return view_.camera_position + t * direction;
    }

    // Continuous pixel-centre coordinates of a world point (pixel (i, j) at (i, j)), and whether
    // the point lies in front of the eye and, when in_frustum is asked for, inside the depth
    // range and the image's outer edges.
    bool project(const glm::dvec3& point, glm::dvec2& q, bool in_frustum) const {
        const glm::dvec4 clip = view_.view_proj * glm::dvec4(point, 1.0);
        if (!(clip.w > 0.0)) return false;
        q.x = (clip.x / clip.w + 1.0) * 0.5 * view_.width - 0.5;
        q.y = (clip.y / clip.w + 1.0) * 0.5 * view_.height - 0.5;
        if (!(std::isfinite(q.x) && std::isfinite(q.y))) return false;
        if (!in_frustum) return true;
        const double depth = clip.z / clip.w;
        return depth >= 0.0 && depth <= 1.0 && q.x >= -0.5 && q.x <= view_.width - 0.5 &&
               q.y >= -0.5 && q.y <= view_.height - 0.5;
    }

  private:
    const StereoAoView& view_;
    glm::dmat4 inverse_;
    glm::dvec3 forward_;
    double eye_depth_;
};

// Forward or backward difference of positions along one axis, whichever is shorter among the
// neighbours that exist; NaN when neither does.
glm::dvec3 shorter_difference(const glm::dvec3& before, const glm::dvec3& at,
                              const glm::dvec3& after) {
    const glm::dvec3 forward = after - at;
    const glm::dvec3 backward = at - before;
    const bool has_forward = is_finite(forward);
    const bool has_backward = is_finite(backward);
    if (has_forward && has_backward) {
        return glm::dot(forward, forward) <= glm::dot(backward, backward) ? forward : backward;
    }
    if (has_forward) return forward;
    if (has_backward) return backward;
    return glm::dvec3(kNaN);
}

// Unit normals of every pixel of a view, facing its eye; NaN where there is none. Positions are
// computed a row at a time, three rows kept. Fails when a non-sky pixel has no world point.
Result<std::vector<glm::vec3>> view_normals(const Eye& eye, const char* name) {
    const std::uint32_t width = eye.width();
    const std::uint32_t height = eye.height();
    const std::vector<glm::dvec3> no_row(width, glm::dvec3(kNaN));
    std::vector<glm::dvec3> above = no_row;
    std::vector<glm::dvec3> row(width);
    std::vector<glm::dvec3> below(width);
    const auto fill = [&](std::uint32_t j, std::vector<glm::dvec3>& out) -> std::string {
        for (std::uint32_t i = 0; i < width; ++i) {
            out[i] = eye.world_point(i, j);
            if (!eye.sky(i, j) && !is_finite(out[i])) {
                return std::string("stereo inconsistency: pixel ") + pixel_text(i, j) + " of the " +
                       name +
                       " view has no point at its depth along its ray; its view_proj, "
                       "camera_position and the head's forward do not belong together";
            }
        }
        return {};
    };
    if (std::string problem = fill(0, row); !problem.empty()) return Error{problem};

    std::vector<glm::vec3> normals(std::size_t{width} * height, glm::vec3(std::nanf("")));
    for (std::uint32_t j = 0; j < height; ++j) {
        if (j + 1 < height) {
            if (std::string problem = fill(j + 1, below); !problem.empty()) return Error{problem};
        } else {
            below = no_row;
        }
        for (std::uint32_t i = 0; i < width; ++i) {
            const glm::dvec3& at = row[i];
            if (!is_finite(at)) continue;
            const glm::dvec3 dx = shorter_difference(i > 0 ? row[i - 1] : glm::dvec3(kNaN), at,
                                                     i + 1 < width ? row[i + 1] : glm::dvec3(kNaN));
            const glm::dvec3 dy = shorter_difference(above[i], at, below[i]);
            glm::dvec3 normal = glm::cross(dx, dy);
            const double length = glm::length(normal);
            if (!(std::isfinite(length) && length > 0.0)) continue;
            normal /= length;
            if (glm::dot(normal, eye.position() - at) < 0.0) normal = -normal;
            normals[eye.index(i, j)] = glm::vec3(normal);
        }
        std::swap(above, row);
        std::swap(row, below);
    }
    return normals;
}

double snap(double coordinate) {
    const double centre = std::round(coordinate);
    return std::abs(coordinate - centre) <= kSnapPx ? centre : coordinate;
}

// The left eye's pixels against the right eye's view of the same surface points.
class EyeComparison {
  public:
    EyeComparison(const Eye& left, const Eye& right, const std::vector<glm::vec3>& left_normals,
                  const std::vector<glm::vec3>& right_normals, const InconsistencyOptions& options)
        : left_(left),
          right_(right),
          left_normals_(left_normals),
          right_normals_(right_normals),
          back_check_px_(options.back_check_px),
          min_cosine_(std::cos(options.normal_threshold_deg * std::numbers::pi / 180.0)) {}

    // What left pixel (i, j) is; for a compared pixel, error is |AO left - AO right there|.
    InconsistencyClass classify(std::uint32_t i, std::uint32_t j, double& error) const {
        if (left_.sky(i, j)) return InconsistencyClass::sky;
        const std::optional<glm::dvec2> q = seen_by_right(i, j);
        if (!q) return InconsistencyClass::one_eye_only;
        const glm::dvec3 normal(left_normals_[left_.index(i, j)]);
        if (!is_finite(normal)) return InconsistencyClass::normal_rejected;
        const std::optional<double> right_ao = right_ao_at(*q, normal);
        if (!right_ao) return InconsistencyClass::normal_rejected;
        error = std::abs(static_cast<double>(left_.ao(i, j)) - *right_ao);
        return InconsistencyClass::compared;
    }

  private:
    // Visibility: reverse reprojection with back-check. Where the right eye sees left pixel
    // (i, j)'s point, in its continuous pixel coordinates; nothing when the point lies outside
    // its view or the right eye sees something else there.
    std::optional<glm::dvec2> seen_by_right(std::uint32_t i, std::uint32_t j) const {
        const glm::dvec3 point = left_.world_point(i, j);
        glm::dvec2 q;
        if (!right_.project(point, q, true)) return std::nullopt;
        const auto nearest = [](double coordinate, std::uint32_t size) {
            return static_cast<std::uint32_t>(
                std::clamp(std::floor(coordinate + 0.5), 0.0, static_cast<double>(size - 1)));
        };
        const glm::dvec3 seen =
            right_.world_point(nearest(q.x, right_.width()), nearest(q.y, right_.height()));
        glm::dvec2 back;
        if (!is_finite(seen) || !left_.project(seen, back, false) ||
            !(glm::length(back - glm::dvec2(i, j)) <= back_check_px_)) {
            return std::nullopt;
        }
        return q;
    }

    // The right eye's AO interpolated bilinearly at q; nothing when a pixel of the footprint
    // lies outside the image or faces more than the threshold away from `normal`.
    std::optional<double> right_ao_at(const glm::dvec2& q, const glm::dvec3& normal) const {
        const double x = snap(q.x);
        const double y = snap(q.y);
        const double x0 = std::floor(x);
        const double y0 = std::floor(y);
        const double fx = x - x0;
        const double fy = y - y0;
        double interpolated = 0.0;
        for (int dy = 0; dy < 2; ++dy) {
            const double wy = dy == 0 ? 1.0 - fy : fy;
            if (wy == 0.0) continue;
            for (int dx = 0; dx < 2; ++dx) {
                const double wx = dx == 0 ? 1.0 - fx : fx;
                if (wx == 0.0) continue;
                const double xi = x0 + dx;
                const double yi = y0 + dy;
                if (xi < 0.0 || yi < 0.0 || xi >= right_.width() || yi >= right_.height()) {
                    return std::nullopt;
                }
                const auto ri = static_cast<std::uint32_t>(xi);
                const auto rj = static_cast<std::uint32_t>(yi);
                const glm::dvec3 other(right_normals_[right_.index(ri, rj)]);
                if (!is_finite(other) || !(glm::dot(normal, other) >= min_cosine_)) {
                    return std::nullopt;
                }
                interpolated += wx * wy * right_.ao(ri, rj);
            }
        }
        return interpolated;
    }

    const Eye& left_;
    const Eye& right_;
    const std::vector<glm::vec3>& left_normals_;
    const std::vector<glm::vec3>& right_normals_;
    double back_check_px_;
    double min_cosine_;
};

void count_class(InconsistencyClass kind, InconsistencyMap& map) {
    switch (kind) {
        case InconsistencyClass::compared:
            ++map.compared;
            break;
        case InconsistencyClass::sky:
            ++map.sky;
            break;
        case InconsistencyClass::one_eye_only:
            ++map.one_eye_only;
            break;
        case InconsistencyClass::normal_rejected:
            ++map.normal_rejected;
            break;
    }
}

}  // namespace

Result<InconsistencyMap> stereo_inconsistency(const StereoAoView& left, const StereoAoView& right,
                                              const StereoHead& head,
                                              const InconsistencyOptions& options) {
    for (const std::string& problem : {check_view(left, "left"), check_view(right, "right"),
                                       check_head_and_options(head, options)}) {
        if (!problem.empty()) return Error{problem};
    }
    const Eye left_eye(left, head);
    const Eye right_eye(right, head);
    Result<std::vector<glm::vec3>> left_normals = view_normals(left_eye, "left");
    if (!left_normals) return left_normals.error();
    Result<std::vector<glm::vec3>> right_normals = view_normals(right_eye, "right");
    if (!right_normals) return right_normals.error();
    const EyeComparison comparison(left_eye, right_eye, *left_normals, *right_normals, options);

    InconsistencyMap map;
    map.width = left.width;
    map.height = left.height;
    const std::size_t pixels = std::size_t{left.width} * left.height;
    map.error.assign(pixels, std::nanf(""));
    map.classes.assign(pixels, InconsistencyClass::compared);
    double sum = 0.0;
    for (std::uint32_t j = 0; j < left.height; ++j) {
        for (std::uint32_t i = 0; i < left.width; ++i) {
            const std::size_t k = left_eye.index(i, j);
            double error = 0.0;
            const InconsistencyClass kind = comparison.classify(i, j, error);
            if (kind == InconsistencyClass::compared) {
                map.error[k] = static_cast<float>(error);
                sum += error;
                map.max = std::max(map.max, error);
            }
            map.classes[k] = kind;
            count_class(kind, map);
        }
    }
    if (map.compared > 0) map.mean = sum / static_cast<double>(map.compared);
    return map;
}

std::vector<std::uint8_t> inconsistency_heat_map_rgba(const InconsistencyMap& map, float scale) {
    // A wrong scale or a hand-made map is a programming error; checked in release builds too, so
    // it cannot turn a researcher's figure silently black or read out of bounds.
    const std::size_t pixels = std::size_t{map.width} * map.height;
    if (!(std::isfinite(scale) && scale > 0.0f) || map.error.size() != pixels ||
        map.classes.size() != pixels) {
        std::fprintf(stderr,
                     "inconsistency_heat_map_rgba: needs scale > 0 and finite (got %g) and a map "
                     "from stereo_inconsistency (%zu errors, %zu classes for %ux%u)\n",
                     static_cast<double>(scale), map.error.size(), map.classes.size(), map.width,
                     map.height);
        std::abort();
    }
    std::vector<std::uint8_t> rgba(pixels * 4);
    for (std::size_t k = 0; k < pixels; ++k) {
        Rgba8 colour = kNoErrorRgba;
        if (map.classes[k] == InconsistencyClass::compared) {
            const Rgb8 heat = inferno(std::clamp(map.error[k] * scale, 0.0f, 1.0f));
            colour = {heat[0], heat[1], heat[2], 255};
        } else if (map.classes[k] == InconsistencyClass::one_eye_only) {
            colour = kOneEyeOnlyRgba;
        }
        std::copy(colour.begin(), colour.end(), rgba.begin() + static_cast<std::ptrdiff_t>(4 * k));
    }
    return rgba;
}

}  // namespace monoplane::quality
