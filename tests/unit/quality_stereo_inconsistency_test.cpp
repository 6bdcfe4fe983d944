// Stereo inconsistency (papers/002 Sect. 4.1) on a stereo pair ray-cast in this file: expected
// classes and errors come from the analytic scene (which surface each eye's ray hits, whether the
// right eye's ray to a point is blocked, where a point lands in the right image by its tangents),
// not from the code under test.
//
// Scene (metres, world = head frame of the default head at the origin looking down -z):
//   floor      y = -1,  x <= 2, z >= -5
//   back wall  z = -5,  x <= 2, -1 <= y <= 1 (sky above it)
//   side wall  x = 2,   -5 <= z <= 0, -1 <= y <= 1: a vertical crease with the back wall
//   box        [-0.5, -0.1] x [-0.5, 0.1] x [-1.9, -1.5], floating left of the view axis
// Eyes at x = -/+ 0.032, 120 x 90 pixels, tangents +-0.6 by +-0.45 (square pixels, 100 px per
// unit tangent), so a point at depth z has a disparity of 0.064 * 100 / z px (1.28 px on the back
// wall, 4.3 px on the box) and lands on the same row in both eyes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include <glm/ext/matrix_double3x3.hpp>
#include <glm/ext/quaternion_double.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "renderer/quality/colormap.h"
#include "renderer/quality/stereo_inconsistency.h"
#include "rig/pose.h"
#include "rig/projection.h"

namespace monoplane::quality {
namespace {

constexpr std::uint32_t kWidth = 120;
constexpr std::uint32_t kHeight = 90;
constexpr double kTanX = 0.6;
constexpr double kTanY = 0.45;
constexpr double kHalfIpd = 0.032;
constexpr float kSky = 1e30f;

enum Surface : int { kNone = -1, kFloor, kBackWall, kSideWall, kBoxFront, kBoxSide, kBoxOther };

struct Hit {
    double t = INFINITY;  // along the (unnormalised) ray direction
    int surface = kNone;
};

// Nearest intersection of origin + t * direction, t > 0, with the scene.
Hit cast(const glm::dvec3& origin, const glm::dvec3& direction) {
    Hit best;
    const auto consider = [&](double t, int surface, const std::function<bool(glm::dvec3)>& in) {
        if (!(t > 1e-9 && t < best.t)) return;
        if (in(origin + t * direction)) best = {t, surface};
    };
    if (direction.y != 0.0) {
        consider((-1.0 - origin.y) / direction.y, kFloor,
                 [](glm::dvec3 p) { return p.x <= 2.0 && p.z >= -5.0; });
    }
    if (direction.z != 0.0) {
        consider((-5.0 - origin.z) / direction.z, kBackWall,
                 [](glm::dvec3 p) { return p.x <= 2.0 && p.y >= -1.0 && p.y <= 1.0; });
    }
    if (direction.x != 0.0) {
        consider((2.0 - origin.x) / direction.x, kSideWall, [](glm::dvec3 p) {
            return p.z >= -5.0 && p.z <= 0.0 && p.y >= -1.0 && p.y <= 1.0;
        });
    }
    // Box by slabs: the entry face is the one of the largest entry parameter.
    const glm::dvec3 lo(-0.5, -0.5, -1.9);
    const glm::dvec3 hi(-0.1, 0.1, -1.5);
    double enter = -INFINITY;
    double leave = INFINITY;
    int face = kNone;
    for (int a = 0; a < 3; ++a) {
        if (direction[a] == 0.0) {
            if (origin[a] < lo[a] || origin[a] > hi[a]) return best;
            continue;
        }
        double t0 = (lo[a] - origin[a]) / direction[a];
        double t1 = (hi[a] - origin[a]) / direction[a];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > enter) {
            enter = t0;
            face = a == 2 && direction.z < 0.0   ? kBoxFront
                   : a == 0 && direction.x < 0.0 ? kBoxSide
                                                 : kBoxOther;
        }
        leave = std::min(leave, t1);
    }
    if (enter <= leave && enter > 1e-9 && enter < best.t) best = {enter, face};
    return best;
}

struct HeadPose {
    glm::dvec3 position{0.0};
    double yaw = 0.0;
    double pitch = 0.0;
    glm::dmat3 rotation() const {
        return glm::mat3_cast(rig::orientation_from_yaw_pitch(yaw, pitch));
    }
    StereoHead head() const { return {position, rotation() * glm::dvec3(0.0, 0.0, -1.0)}; }
};

// What the test knows about one eye's rendering besides the view itself.
struct Rendered {
    StereoAoView view;
    glm::dvec3 eye{0.0};
    glm::dmat3 rotation{1.0};
    std::vector<int> surface;
    std::vector<glm::dvec3> point;  // world point per pixel (unused for sky)

    std::size_t index(std::uint32_t i, std::uint32_t j) const { return j * kWidth + i; }
    // Continuous pixel-centre coordinates of a world point, from its tangents in this eye.
    glm::dvec2 pixel_of(const glm::dvec3& world) const {
        const glm::dvec3 local = glm::transpose(rotation) * (world - eye);
        const double tan_x = local.x / -local.z;
        const double tan_y = local.y / -local.z;
        return {(tan_x / kTanX + 1.0) * 0.5 * kWidth - 0.5,
                (-tan_y / kTanY + 1.0) * 0.5 * kHeight - 0.5};
    }
    // Whether this eye sees a world point: inside its frustum and not behind something nearer.
    bool sees(const glm::dvec3& world) const {
        const glm::dvec2 q = pixel_of(world);
        if (q.x < -0.5 || q.x > kWidth - 0.5 || q.y < -0.5 || q.y > kHeight - 0.5) return false;
        return cast(eye, world - eye).t >= 1.0 - 1e-6;
    }
};

using AoFunction = std::function<float(const glm::dvec3&, std::uint32_t i, std::uint32_t j)>;

// Ray-casts one eye (side -1 left, +1 right) of the head: pixel (i, j) looks along tangents
// ((i + 0.5) / 120 * 2 - 1) * 0.6 and -((j + 0.5) / 90 * 2 - 1) * 0.45, row 0 at the top.
Rendered render(const HeadPose& pose, int side, const AoFunction& ao) {
    Rendered out;
    const glm::dmat3 rotation = pose.rotation();
    const glm::dvec3 offset(side * kHalfIpd, 0.0, 0.0);
    const StereoHead head = pose.head();
    out.rotation = rotation;
    out.eye = pose.position + rotation * offset;
    out.view.width = kWidth;
    out.view.height = kHeight;
    out.view.camera_position = out.eye;
    out.view.view_proj =
        rig::projection_reversed_z({-kTanX, kTanX, -kTanY, kTanY}, 0.1, 1000.0) *
        rig::view_matrix({pose.position, rig::orientation_from_yaw_pitch(pose.yaw, pose.pitch)},
                         offset);
    const std::size_t pixels = std::size_t{kWidth} * kHeight;
    out.view.linear_depth.resize(pixels);
    out.view.ao.resize(pixels);
    out.surface.resize(pixels);
    out.point.resize(pixels);
    for (std::uint32_t j = 0; j < kHeight; ++j) {
        for (std::uint32_t i = 0; i < kWidth; ++i) {
            const double tan_x = ((i + 0.5) / kWidth * 2.0 - 1.0) * kTanX;
            const double tan_y = -((j + 0.5) / kHeight * 2.0 - 1.0) * kTanY;
            const glm::dvec3 direction = rotation * glm::dvec3(tan_x, tan_y, -1.0);
            const Hit hit = cast(out.eye, direction);
            const std::size_t k = out.index(i, j);
            out.surface[k] = hit.surface;
            if (hit.surface == kNone) {
                out.view.linear_depth[k] = kSky;
                out.view.ao[k] = 1.0f;
                continue;
            }
            const glm::dvec3 point = out.eye + hit.t * direction;
            out.point[k] = point;
            out.view.linear_depth[k] =
                static_cast<float>(glm::dot(point - head.position, head.forward));
            out.view.ao[k] = ao(point, i, j);
        }
    }
    return out;
}

AoFunction constant(float value) {
    return [value](const glm::dvec3&, std::uint32_t, std::uint32_t) { return value; };
}

// Smooth in world space, the same for both eyes: what a perfectly consistent AO looks like.
float smooth_ao(const glm::dvec3& p, std::uint32_t, std::uint32_t) {
    return static_cast<float>(0.5 + 0.2 * std::sin(1.1 * p.x + 0.3) *
                                        std::sin(0.9 * p.y + 0.8 * p.z + 0.1));
}

struct Pair {
    Rendered left;
    Rendered right;
    StereoHead head;
};

Pair render_pair(const AoFunction& left_ao, const AoFunction& right_ao, const HeadPose& pose = {}) {
    return {render(pose, -1, left_ao), render(pose, +1, right_ao), pose.head()};
}

InconsistencyMap evaluate(const Pair& pair, const InconsistencyOptions& options = {}) {
    Result<InconsistencyMap> map =
        stereo_inconsistency(pair.left.view, pair.right.view, pair.head, options);
    EXPECT_TRUE(map.ok()) << (map.ok() ? "" : map.error().message);
    if (!map.ok()) return {};
    return std::move(map).value();
}

std::size_t count_sky(const Rendered& eye) {
    return static_cast<std::size_t>(std::count(eye.surface.begin(), eye.surface.end(), kNone));
}

InconsistencyClass class_at(const InconsistencyMap& map, std::uint32_t i, std::uint32_t j) {
    return map.classes[std::size_t{j} * map.width + i];
}

// The right AO bilinearly interpolated at the left pixel's point, from the test's own projection
// (reads clamped to the image; they only matter with weight ~0 on the border).
double expected_interpolation(const Pair& pair, std::uint32_t i, std::uint32_t j) {
    const glm::dvec2 q = pair.right.pixel_of(pair.left.point[pair.left.index(i, j)]);
    const double x0 = std::floor(q.x);
    const double y0 = std::floor(q.y);
    double sum = 0.0;
    for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) {
            const double w =
                (dx ? q.x - x0 : 1.0 - (q.x - x0)) * (dy ? q.y - y0 : 1.0 - (q.y - y0));
            const auto x = static_cast<std::uint32_t>(std::clamp(x0 + dx, 0.0, kWidth - 1.0));
            const auto y = static_cast<std::uint32_t>(std::clamp(y0 + dy, 0.0, kHeight - 1.0));
            sum += w * pair.right.view.ao[pair.right.index(x, y)];
        }
    }
    return sum;
}

// ----- classes and counts --------------------------------------------------------------------

TEST(StereoInconsistency, CountsEveryPixelOnceAndSkyAsRayCast) {
    const Pair pair = render_pair(constant(0.5f), constant(0.5f));
    const InconsistencyMap map = evaluate(pair);
    ASSERT_EQ(map.width, kWidth);
    ASSERT_EQ(map.height, kHeight);
    ASSERT_EQ(map.error.size(), std::size_t{kWidth} * kHeight);
    ASSERT_EQ(map.classes.size(), map.error.size());

    // Rows 0..24 above the walls' top edge (y = 1 at z = -5 is row 24.5) are sky, apart from the
    // side wall's corner on the right.
    const std::size_t sky = count_sky(pair.left);
    EXPECT_GT(sky, std::size_t{20} * kWidth);
    EXPECT_EQ(map.sky, sky);
    EXPECT_EQ(map.compared + map.sky + map.one_eye_only + map.normal_rejected, map.error.size());
    std::array<std::size_t, 4> tally{};
    for (const InconsistencyClass c : map.classes) ++tally[static_cast<std::size_t>(c)];
    EXPECT_EQ(tally[0], map.compared);
    EXPECT_EQ(tally[1], map.sky);
    EXPECT_EQ(tally[2], map.one_eye_only);
    EXPECT_EQ(tally[3], map.normal_rejected);
    for (std::size_t k = 0; k < map.error.size(); ++k) {
        EXPECT_EQ(std::isnan(map.error[k]), map.classes[k] != InconsistencyClass::compared) << k;
        EXPECT_EQ(map.classes[k] == InconsistencyClass::sky, pair.left.surface[k] == kNone) << k;
    }
    // Exclusions are edges and thin strips: most of the surfaces are compared.
    EXPECT_GT(map.compared, (map.error.size() - sky) * 9 / 10);
    EXPECT_GT(map.one_eye_only, 0u);
    EXPECT_GT(map.normal_rejected, 0u);
    // Identical constant AO: no error anywhere.
    EXPECT_EQ(map.mean, 0.0);
    EXPECT_EQ(map.max, 0.0);
}

// ----- the error value -----------------------------------------------------------------------

TEST(StereoInconsistency, ConstantOffsetIsTheErrorOfEveryComparedPixel) {
    for (const HeadPose& pose : {HeadPose{}, HeadPose{{0.3, 0.1, 0.4}, 0.25, -0.15}}) {
        const Pair pair = render_pair(constant(0.3f), constant(0.4f), pose);
        const InconsistencyMap map = evaluate(pair);
        ASSERT_GT(map.compared, 1000u);
        EXPECT_EQ(map.sky, count_sky(pair.left));
        EXPECT_NEAR(map.mean, 0.1, 1e-4);
        EXPECT_NEAR(map.max, 0.1, 1e-4);
        for (std::size_t k = 0; k < map.error.size(); ++k) {
            if (map.classes[k] == InconsistencyClass::compared) {
                ASSERT_NEAR(map.error[k], 0.1, 1e-6) << k;
            }
        }
    }
}

TEST(StereoInconsistency, ErrorIsTheDifferenceToTheBilinearlyInterpolatedRightAo) {
    // White noise in the right view makes the interpolated value depend sharply on where the
    // point lands and on the weights, which the test computes from the scene's geometry.
    std::mt19937 rng(11);
    std::vector<float> noise(std::size_t{kWidth} * kHeight);
    for (float& v : noise) v = static_cast<float>(rng() >> 8) / 16777216.0f;
    const AoFunction right_ao = [&noise](const glm::dvec3&, std::uint32_t i, std::uint32_t j) {
        return noise[std::size_t{j} * kWidth + i];
    };
    const Pair pair = render_pair(constant(0.5f), right_ao);
    const InconsistencyMap map = evaluate(pair);
    ASSERT_GT(map.compared, 1000u);
    double sum = 0.0;
    for (std::uint32_t j = 0; j < kHeight; ++j) {
        for (std::uint32_t i = 0; i < kWidth; ++i) {
            if (class_at(map, i, j) != InconsistencyClass::compared) continue;
            const double expected = std::abs(0.5 - expected_interpolation(pair, i, j));
            // Depth is float: the point, and so q, is off by ~1e-5 px; noise changes by <= 1/px.
            ASSERT_NEAR(map.error[pair.left.index(i, j)], expected, 1e-3) << i << ", " << j;
            sum += map.error[pair.left.index(i, j)];
        }
    }
    EXPECT_NEAR(map.mean, sum / map.compared, 1e-9);
}

TEST(StereoInconsistency, ConsistentSmoothAoHasSmallError) {
    const Pair pair = render_pair(smooth_ao, smooth_ao);
    const InconsistencyMap map = evaluate(pair);
    ASSERT_GT(map.compared, 1000u);
    // The AO's second derivative along any direction is at most 0.2 * (1.1^2 + 0.9^2 + 0.8^2)
    // = 0.53 per m^2, and neighbouring pixels are at most ~0.25 m apart (the side wall seen at a
    // grazing angle), so linear interpolation errs by at most 0.53 * 0.25^2 / 8 = 0.004 where the
    // footprint stays on one surface. Where it straddles a silhouette onto a parallel surface
    // (box front and back wall) the normal check cannot tell, but those are a few dozen pixels.
    std::size_t straddling = 0;
    for (std::uint32_t j = 0; j < kHeight; ++j) {
        for (std::uint32_t i = 0; i < kWidth; ++i) {
            if (class_at(map, i, j) != InconsistencyClass::compared) continue;
            const std::size_t k = pair.left.index(i, j);
            const glm::dvec2 q = pair.right.pixel_of(pair.left.point[k]);
            // The right pixels with a noticeable bilinear weight.
            bool one_surface = true;
            for (int d = 0; d < 4; ++d) {
                const double fx = q.x - std::floor(q.x);
                const double fy = q.y - std::floor(q.y);
                if ((d & 1 ? fx : 1.0 - fx) * (d >> 1 ? fy : 1.0 - fy) < 1e-3) continue;
                const auto x = static_cast<std::uint32_t>(
                    std::clamp(std::floor(q.x) + (d & 1), 0.0, kWidth - 1.0));
                const auto y = static_cast<std::uint32_t>(
                    std::clamp(std::floor(q.y) + (d >> 1), 0.0, kHeight - 1.0));
                one_surface &= pair.right.surface[pair.right.index(x, y)] == pair.left.surface[k];
            }
            if (one_surface) {
                EXPECT_LT(map.error[k], 0.005) << i << ", " << j;
            } else {
                ++straddling;
            }
        }
    }
    EXPECT_LT(straddling, 100u);
    EXPECT_LT(map.mean, 0.01);
}

// ----- visibility ----------------------------------------------------------------------------

TEST(StereoInconsistency, PointsTheRightEyeCannotSeeAreOneEyeOnly) {
    const Pair pair = render_pair(constant(0.3f), constant(0.4f));
    const InconsistencyMap map = evaluate(pair);

    // Pixel (27, 50) of the left eye looks along tangents (-0.325, -0.055) past the box's left
    // edge (x = -0.032 - 0.325 * 1.5 = -0.52 < -0.5 at the box's front) onto the back wall at
    // (-1.657, -0.275, -5). From the right eye that point lies behind the box: its ray crosses
    // z = -1.5 at x = 0.032 - 1.689 * 0.3 = -0.475, y = -0.083, inside the front face.
    const std::size_t k = pair.left.index(27, 50);
    ASSERT_EQ(pair.left.surface[k], kBackWall);
    EXPECT_NEAR(pair.left.point[k].x, -1.657, 1e-3);
    ASSERT_FALSE(pair.right.sees(pair.left.point[k]));
    EXPECT_EQ(class_at(map, 27, 50), InconsistencyClass::one_eye_only);
    EXPECT_TRUE(std::isnan(map.error[k]));

    // Everywhere: a point hidden from the right eye (occluded or outside its frustum), with its
    // 3 x 3 neighbours hidden too, is one eye only; a point the right eye sees, with its 5 x 5
    // neighbours seen too and on the same surface, landing 2 px inside the right image, is not.
    // (Within about a pixel of an occlusion boundary or a silhouette the back-check depends on
    // what the nearest right pixel happens to see: at the box's side face, one pixel wide in the
    // left eye, the right pixel on the same row may already pass above the box's top edge.)
    const auto hidden = [&](std::uint32_t i, std::uint32_t j) {
        const std::size_t n = pair.left.index(i, j);
        return pair.left.surface[n] != kNone && !pair.right.sees(pair.left.point[n]);
    };
    const auto visible_on = [&](int surface) {
        return [&pair, surface](std::uint32_t i, std::uint32_t j) {
            const std::size_t n = pair.left.index(i, j);
            return pair.left.surface[n] == surface && pair.right.sees(pair.left.point[n]);
        };
    };
    const auto all_around = [](std::uint32_t i, std::uint32_t j, int r, auto&& predicate) {
        for (int dj = -r; dj <= r; ++dj) {
            for (int di = -r; di <= r; ++di) {
                const int x = static_cast<int>(i) + di;
                const int y = static_cast<int>(j) + dj;
                if (x < 0 || y < 0 || x >= static_cast<int>(kWidth) ||
                    y >= static_cast<int>(kHeight)) {
                    continue;
                }
                if (!predicate(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)))
                    return false;
            }
        }
        return true;
    };
    std::size_t surely_hidden = 0;
    std::size_t surely_visible = 0;
    for (std::uint32_t j = 0; j < kHeight; ++j) {
        for (std::uint32_t i = 0; i < kWidth; ++i) {
            if (all_around(i, j, 1, hidden)) {
                ++surely_hidden;
                EXPECT_EQ(class_at(map, i, j), InconsistencyClass::one_eye_only) << i << ", " << j;
            }
            const glm::dvec2 q = pair.right.pixel_of(pair.left.point[pair.left.index(i, j)]);
            if (all_around(i, j, 2, visible_on(pair.left.surface[pair.left.index(i, j)])) &&
                q.x >= 2.0 && q.x <= kWidth - 3.0 && q.y >= 2.0 && q.y <= kHeight - 3.0) {
                ++surely_visible;
                EXPECT_NE(class_at(map, i, j), InconsistencyClass::one_eye_only) << i << ", " << j;
            }
        }
    }
    // The strip of wall behind the box's left edge (columns 26-28, rows ~38-64) and the left
    // image border, where the right frustum ends.
    EXPECT_GT(surely_hidden, 40u);
    EXPECT_GT(surely_visible, 5000u);
    EXPECT_GE(map.one_eye_only, surely_hidden);

    // The back-check is what finds the occlusion: with a tolerance larger than the box's
    // disparity against the wall (4.3 - 1.3 = 3 px), the hidden wall pixel passes it.
    InconsistencyOptions lax;
    lax.back_check_px = 10.0;
    EXPECT_NE(class_at(evaluate(pair, lax), 27, 50), InconsistencyClass::one_eye_only);
}

// ----- normal check --------------------------------------------------------------------------

TEST(StereoInconsistency, PixelsAtTheVerticalCreaseAreNormalRejected) {
    const Pair pair = render_pair(constant(0.3f), constant(0.4f));
    const InconsistencyMap map = evaluate(pair);
    InconsistencyOptions no_normal_check;
    no_normal_check.normal_threshold_deg = 180.0;
    const InconsistencyMap lax = evaluate(pair, no_normal_check);

    // The corner x = 2, z = -5 is at tangent 2.032 / 5 = 0.4064 in the left eye (column 100.14)
    // and 1.968 / 5 = 0.3936 in the right (column 98.86). The left pixels either side of it land
    // in the right image between a back-wall and a side-wall pixel, or next to a pixel whose
    // normal had to be taken across the corner (>= 20 degrees off either wall for this layout),
    // so the normal check fails; without it they are compared. Three columns away, each wall is
    // flat in both eyes and compared.
    for (std::uint32_t j = 30; j <= 60; ++j) {
        std::uint32_t last_back = 0;
        for (std::uint32_t i = 0; i < kWidth; ++i) {
            if (pair.left.surface[pair.left.index(i, j)] == kBackWall) last_back = i;
        }
        ASSERT_EQ(pair.left.surface[pair.left.index(last_back + 1, j)], kSideWall);
        EXPECT_EQ(class_at(map, last_back, j), InconsistencyClass::normal_rejected) << j;
        EXPECT_EQ(class_at(map, last_back + 1, j), InconsistencyClass::normal_rejected) << j;
        EXPECT_EQ(class_at(lax, last_back, j), InconsistencyClass::compared) << j;
        EXPECT_EQ(class_at(lax, last_back + 1, j), InconsistencyClass::compared) << j;
        EXPECT_EQ(class_at(map, last_back - 3, j), InconsistencyClass::compared) << j;
        EXPECT_EQ(class_at(map, last_back + 4, j), InconsistencyClass::compared) << j;
    }
    EXPECT_LT(lax.normal_rejected, map.normal_rejected);
    EXPECT_EQ(lax.one_eye_only, map.one_eye_only);
}

TEST(StereoInconsistency, ParallelEyesReadAlongRowsOnly) {
    // With the eyes side by side every point lands on its own row in the right image, so the
    // footprint is one row: the bottom row's floor pixels are compared (a 2 x 2 footprint would
    // reach below the image), and so are the floor and wall pixels along their horizontal crease
    // (row 64.5), which the interpolation never crosses.
    const Pair pair = render_pair(smooth_ao, smooth_ao);
    const InconsistencyMap map = evaluate(pair);
    for (std::uint32_t i = 60; i < 90; ++i) {
        ASSERT_EQ(pair.left.surface[pair.left.index(i, kHeight - 1)], kFloor);
        EXPECT_EQ(class_at(map, i, kHeight - 1), InconsistencyClass::compared) << i;
        ASSERT_EQ(pair.left.surface[pair.left.index(i, 64)], kBackWall);
        ASSERT_EQ(pair.left.surface[pair.left.index(i, 65)], kFloor);
        EXPECT_EQ(class_at(map, i, 64), InconsistencyClass::compared) << i;
        EXPECT_EQ(class_at(map, i, 65), InconsistencyClass::compared) << i;
        EXPECT_LT(map.error[pair.left.index(i, 65)], 0.005) << i;
    }
}

// ----- bad input -----------------------------------------------------------------------------

TEST(StereoInconsistency, RejectsMalformedInput) {
    const Pair good = render_pair(constant(0.5f), constant(0.5f));
    ASSERT_TRUE(stereo_inconsistency(good.left.view, good.right.view, good.head).ok());
    const auto fails = [&](const StereoAoView& left, const StereoAoView& right,
                           const StereoHead& head, const InconsistencyOptions& options = {}) {
        const Result<InconsistencyMap> map = stereo_inconsistency(left, right, head, options);
        if (map.ok()) return false;
        EXPECT_FALSE(map.error().message.empty());
        return true;
    };
    const StereoAoView& l = good.left.view;
    const StereoAoView& r = good.right.view;
    const StereoHead& h = good.head;

    StereoAoView v = l;
    v.ao.pop_back();
    EXPECT_TRUE(fails(v, r, h)) << "AO shorter than width * height";
    v = r;
    v.linear_depth.push_back(1.0f);
    EXPECT_TRUE(fails(l, v, h)) << "depth longer than width * height";
    v = l;
    v.height = 89;
    EXPECT_TRUE(fails(v, r, h)) << "size that does not match the data";
    EXPECT_TRUE(fails(StereoAoView{}, r, h)) << "empty view";
    EXPECT_TRUE(fails(l, StereoAoView{}, h)) << "empty view";
    v = l;
    v.view_proj[2][1] = NAN;
    EXPECT_TRUE(fails(v, r, h)) << "NaN matrix";
    v = r;
    v.view_proj = glm::dmat4(0.0);
    EXPECT_TRUE(fails(l, v, h)) << "singular matrix";
    v = l;
    v.view_proj = glm::dmat4(1.0);
    EXPECT_TRUE(fails(v, r, h)) << "orthographic matrix";
    v = l;
    v.camera_position = r.camera_position;
    EXPECT_TRUE(fails(v, r, h)) << "eye position not the matrix's";
    v = l;
    v.camera_position.x = INFINITY;
    EXPECT_TRUE(fails(v, r, h)) << "infinite eye position";
    v = l;
    v.linear_depth[4000] = NAN;
    EXPECT_TRUE(fails(v, r, h)) << "NaN depth";
    v = l;
    v.linear_depth[4000] = -2.0f;
    EXPECT_TRUE(fails(v, r, h)) << "negative depth";
    v = l;
    ASSERT_NE(good.left.surface[4000], kNone);
    v.ao[4000] = NAN;
    EXPECT_TRUE(fails(v, r, h)) << "NaN AO on a surface";
    v = l;
    ASSERT_EQ(good.left.surface[0], kNone);
    v.ao[0] = NAN;
    EXPECT_FALSE(fails(v, r, h)) << "the sky's AO is not read";
    v.linear_depth[0] = INFINITY;
    EXPECT_FALSE(fails(v, r, h)) << "infinite depth is sky";

    EXPECT_TRUE(fails(l, r, {h.position, glm::dvec3(0.0)})) << "zero forward";
    EXPECT_TRUE(fails(l, r, {h.position, 2.0 * h.forward})) << "forward not unit length";
    EXPECT_TRUE(fails(l, r, {glm::dvec3(NAN), h.forward})) << "NaN head";
    EXPECT_TRUE(fails(l, r, {h.position, -h.forward})) << "depths measured backwards";

    for (const double px : {0.0, -1.0, double{NAN}, double{INFINITY}}) {
        EXPECT_TRUE(fails(l, r, h, {px, 6.0})) << "back-check " << px;
    }
    for (const double deg : {-1.0, 181.0, double{NAN}}) {
        EXPECT_TRUE(fails(l, r, h, {1.0, deg})) << "threshold " << deg;
    }
}

// ----- heat map ------------------------------------------------------------------------------

TEST(StereoInconsistency, HeatMapColours) {
    const Pair pair = render_pair(constant(0.3f), constant(0.4f));
    const InconsistencyMap map = evaluate(pair);
    // Pixels of each class, found from the scene: the back wall's interior (both eyes see it,
    // flat), the hidden strip behind the box, the sky, the vertical crease.
    const std::uint32_t compared_i = 80, compared_j = 40;
    ASSERT_EQ(class_at(map, compared_i, compared_j), InconsistencyClass::compared);
    ASSERT_EQ(class_at(map, 27, 50), InconsistencyClass::one_eye_only);
    ASSERT_EQ(pair.left.surface[pair.left.index(60, 5)], kNone);
    ASSERT_EQ(class_at(map, 60, 5), InconsistencyClass::sky);
    std::uint32_t crease_i = 0;
    while (pair.left.surface[pair.left.index(crease_i + 1, 40)] != kSideWall) ++crease_i;
    ASSERT_EQ(class_at(map, crease_i, 40), InconsistencyClass::normal_rejected);

    const auto pixel = [](const std::vector<std::uint8_t>& rgba, std::uint32_t i, std::uint32_t j) {
        const std::size_t k = 4 * (std::size_t{j} * kWidth + i);
        return std::array<int, 4>{rgba[k], rgba[k + 1], rgba[k + 2], rgba[k + 3]};
    };
    using Colour = std::array<int, 4>;
    // colormap.h: inferno(1) = (252, 255, 164), inferno(0.5) = (188, 55, 84), inferno(0) =
    // (0, 0, 4). E = 0.1 magnified 20x saturates; 5x gives 0.5.
    const std::vector<std::uint8_t> rgba = inconsistency_heat_map_rgba(map);
    ASSERT_EQ(rgba.size(), std::size_t{kWidth} * kHeight * 4);
    EXPECT_EQ(pixel(rgba, compared_i, compared_j), (Colour{252, 255, 164, 255}));
    EXPECT_EQ(pixel(rgba, 27, 50), (Colour{160, 32, 240, 255}));
    EXPECT_EQ(pixel(rgba, 60, 5), (Colour{0, 0, 0, 255}));
    EXPECT_EQ(pixel(rgba, crease_i, 40), (Colour{0, 0, 0, 255}));
    EXPECT_EQ(pixel(inconsistency_heat_map_rgba(map, 5.0f), compared_i, compared_j),
              (Colour{188, 55, 84, 255}));

    const InconsistencyMap same = evaluate(render_pair(constant(0.4f), constant(0.4f)));
    EXPECT_EQ(pixel(inconsistency_heat_map_rgba(same), compared_i, compared_j),
              (Colour{0, 0, 4, 255}));
}

}  // namespace
}  // namespace monoplane::quality
