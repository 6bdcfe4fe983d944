// The gaze point and hybrid's error there (app/commands/gaze_point.h): a head at a known place
// looking at a wall at a known distance, over it at the sky, and at a box nearer than the plane.
// The expectations come from the geometry of Fig. 2 written out here: C at s = d / 2 behind the
// eyes for fields of tangent +-1 (eq. 1), a point beyond m shown at its central projection from C
// onto the plane z = -m.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "app/commands/gaze_point.h"
#include "rig/pose.h"

namespace monoplane::app {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kArcmin = 60.0 * 180.0 / kPi;
constexpr double kIpd = 0.064;

void add_quad(scenes::Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    scenes::Chunk chunk;
    chunk.first_index = static_cast<std::uint32_t>(scene.indices.size());
    chunk.vertex_offset = static_cast<std::int32_t>(scene.vertices.size());
    chunk.index_count = 6;
    for (const glm::vec3& p : {a, b, c, d}) {
        scene.vertices.push_back(scenes::Vertex{p, {0.0f, 0.0f, 1.0f}, 0xffffffffu, 0});
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(i);
    scene.chunks.push_back(chunk);
}

// A wall 12 m ahead of the seat at (0, 1.7, 0), 4 m high, and one 12 m to its left.
scenes::Scene walls() {
    scenes::Scene scene;
    add_quad(scene, {-6, 0, -12}, {6, 0, -12}, {6, 4, -12}, {-6, 4, -12});
    add_quad(scene, {-12, 0, 6}, {-12, 0, -6}, {-12, 4, -6}, {-12, 4, 6});
    return scene;
}

rig::RigInputs inputs(double m) {
    rig::RigInputs in;
    in.eyes = {rig::Tangents{-1, 1, -1, 1}, rig::Tangents{-1, 1, -1, 1}};
    in.eye_width = in.eye_height = 1000;
    in.ipd = kIpd;
    in.mono_plane = m;
    return in;
}

rig::Pose seat(double yaw_deg = 0.0) {
    return {{0.0, 1.7, 0.0}, rig::orientation_from_yaw_pitch(yaw_deg * kPi / 180.0, 0.0)};
}

// Each eye's error for a point straight ahead of the eyes' midpoint at depth z: the point shows
// at (0, 0, -m) whatever s is.
double straight_ahead_arcmin(double m, double z) {
    return (std::atan(kIpd / 2 / m) - std::atan(kIpd / 2 / z)) * kArcmin;
}

TEST(GazePoint, AWallStraightAheadAtAKnownDistance) {
    const scenes::Scene scene = walls();
    const auto caster = scenes::SceneRayCaster::build(scene).value_or_throw();
    const rig::Rig rig = rig::build_rig(inputs(3.0)).value_or_throw();
    const auto point = gaze_point(*caster, seat(), rig, {0.0, 0.0, -1.0});
    ASSERT_TRUE(point);
    ASSERT_TRUE(point->depth_m);
    EXPECT_NEAR(*point->depth_m, 12.0, 1e-5);
    EXPECT_EQ(point->mono_plane_m, 3.0);
    EXPECT_TRUE(point->beyond_mono_plane());
    EXPECT_NEAR(point->error_arcmin, straight_ahead_arcmin(3.0, 12.0), 1e-4);
    EXPECT_NEAR(point->error_arcmin, 27.5006, 1e-3);
    // Turned 90 degrees left, the other wall, 12 m away too: the same point in the head's frame.
    const auto turned = gaze_point(*caster, seat(90.0), rig, {0.0, 0.0, -1.0});
    ASSERT_TRUE(turned && turned->depth_m);
    EXPECT_NEAR(*turned->depth_m, 12.0, 1e-5);
    EXPECT_NEAR(turned->error_arcmin, point->error_arcmin, 1e-4);
}

// Looking 40 degrees up, over the wall (its top is 10.8 degrees up): the sky, infinitely far.
TEST(GazePoint, OverTheWallIsTheSkyAtInfinity) {
    const scenes::Scene scene = walls();
    const auto caster = scenes::SceneRayCaster::build(scene).value_or_throw();
    const double m = 3.0;
    const rig::Rig rig = rig::build_rig(inputs(m)).value_or_throw();
    const double up = 40.0 * kPi / 180.0;
    const glm::dvec3 u(0.0, std::sin(up), -std::cos(up));
    const auto point = gaze_point(*caster, seat(), rig, u);
    ASSERT_TRUE(point);
    EXPECT_FALSE(point->depth_m);
    EXPECT_TRUE(point->beyond_mono_plane());
    // C at (0, 0, s), s = d / 2; hybrid shows the sky's point where C's ray along u meets the
    // plane; each eye sees it there instead of along u.
    const double s = kIpd / 2;
    const glm::dvec3 shown = glm::dvec3(0.0, 0.0, s) + u * ((m + s) / std::cos(up));
    double larger = 0.0;
    for (const double x_e : {-kIpd / 2, kIpd / 2}) {
        const glm::dvec3 seen = glm::normalize(shown - glm::dvec3(x_e, 0.0, 0.0));
        larger = std::max(larger, std::acos(std::clamp(glm::dot(seen, u), -1.0, 1.0)) * kArcmin);
    }
    EXPECT_GT(larger, 30.0);
    EXPECT_NEAR(point->error_arcmin, larger, 1e-3);
}

TEST(GazePoint, ABoxNearerThanThePlaneHasNoError) {
    scenes::Scene scene = walls();
    add_quad(scene, {-0.5f, 1, -2}, {0.5f, 1, -2}, {0.5f, 2.5f, -2}, {-0.5f, 2.5f, -2});
    const auto caster = scenes::SceneRayCaster::build(scene).value_or_throw();
    const rig::Rig rig = rig::build_rig(inputs(3.0)).value_or_throw();
    const auto point = gaze_point(*caster, seat(), rig, {0.0, 0.0, -1.0});
    ASSERT_TRUE(point && point->depth_m);
    EXPECT_NEAR(*point->depth_m, 2.0, 1e-5);
    EXPECT_FALSE(point->beyond_mono_plane());
    EXPECT_EQ(point->error_arcmin, 0.0);
}

TEST(GazePoint, TheFinderKnowsItsScenesAndTheTrialsPlane) {
    const scenes::Scene scene = walls();
    auto finder = GazePointFinder::build({{"walls", &scene}}).value_or_throw();
    const auto found = finder->find("walls", seat(), inputs(3.0), {0.0, 0.0, -1.0});
    ASSERT_TRUE(found);
    EXPECT_NEAR(found->error_arcmin, straight_ahead_arcmin(3.0, 12.0), 1e-4);
    // Another m: the rig is built again for it.
    const auto at_eight = finder->find("walls", seat(), inputs(8.0), {0.0, 0.0, -1.0});
    ASSERT_TRUE(at_eight);
    EXPECT_NEAR(at_eight->error_arcmin, straight_ahead_arcmin(8.0, 12.0), 1e-4);
    EXPECT_EQ(at_eight->mono_plane_m, 8.0);
    // A plane at or beyond the far plane: hybrid is stereo there.
    const auto stereo = finder->find("walls", seat(), inputs(1000.0), {0.0, 0.0, -1.0});
    ASSERT_TRUE(stereo);
    EXPECT_EQ(stereo->error_arcmin, 0.0);
    // An adaptive trial before its staircase chose m, and a scene the finder was not given.
    EXPECT_FALSE(finder->find("walls", seat(), inputs(std::nan("")), {0.0, 0.0, -1.0}));
    EXPECT_FALSE(finder->find("beams", seat(), inputs(3.0), {0.0, 0.0, -1.0}));
}

// The session's summary line: quantiles of 1 us bins, the last bin open-ended.
TEST(GazePointCost, QuantilesOfTheLookupsAndTheSummaryLine) {
    GazePointCost cost;
    EXPECT_EQ(cost.quantile_us(0.5), 0.0);
    cost.built(85.25);
    for (const double us : {0.5, 3.2, 3.9, 12000.0}) cost.found(us);
    EXPECT_EQ(cost.lookups(), 4);
    EXPECT_EQ(cost.quantile_us(0.25), 0.0);  // rank 1: the 0.5 us lookup's bin
    EXPECT_EQ(cost.quantile_us(0.5), 3.0);   // rank 2 of 4
    EXPECT_EQ(cost.quantile_us(0.75), 3.0);
    EXPECT_EQ(cost.quantile_us(0.99), 9999.0);  // rank 4: 12 ms, in the open last bin
    EXPECT_EQ(cost.summary(),
              "gaze points: 4 lookups, 3 us each (median), 9999 us (99th percentile); ray "
              "casting prepared in 85.2 ms when the session began\n");
}

}  // namespace
}  // namespace monoplane::app
