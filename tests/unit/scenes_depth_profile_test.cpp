// Unit tests of scenes/depth_profile.h (docs/scenes.md) on a hand-built scene
// whose answer is known exactly: triangles placed at chosen depths in an eye's frame, some inside
// the frustum, some outside it, seen from a turned eye so the orientation matters.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/vec3.hpp>

#include "scenes/depth_profile.h"
#include "scenes/scene.h"

namespace monoplane::scenes {
namespace {

// The HTC Vive's left eye (hmd/profiles/vive.toml).
rig::Tangents vive_left() {
    return {-1.391937, 1.247409, -1.468819, 1.464287};
}

// An eye at kEye turned 90 degrees to the left (yaw +90): its -z looks down world -x, its +x
// points down world -z and its +y is world +y. So the eye-frame point (x, y, -d) lies at world
// kEye + (-d, y, -x), derived by hand, independently of the rig's matrices.
const glm::dvec3 kEye{10.0, 1.5, -4.0};

rig::Pose turned_eye() {
    rig::Pose pose;
    pose.position = kEye;
    pose.orientation = rig::orientation_from_yaw_pitch(std::acos(-1.0) / 2.0, 0.0);
    return pose;
}

glm::vec3 world_of(double x, double y, double depth) {
    return glm::vec3(kEye + glm::dvec3(-depth, y, -x));
}

// Accumulates triangles into two chunks, the second with a vertex offset, as generators do.
struct SceneBuilder {
    Scene scene;
    std::vector<std::uint32_t> second_chunk_indices;
    std::size_t second_chunk_first_vertex = 0;
    bool in_second = false;

    void triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        for (const glm::vec3& p : {a, b, c}) {
            Vertex v{};
            v.position = p;
            v.normal = {0.0f, 1.0f, 0.0f};
            const auto index = static_cast<std::uint32_t>(
                scene.vertices.size() - (in_second ? second_chunk_first_vertex : 0));
            scene.vertices.push_back(v);
            (in_second ? second_chunk_indices : scene.indices).push_back(index);
        }
    }
    // A small triangle whose centroid is the eye-frame point (x, y, -depth).
    void at(double x, double y, double depth) {
        const glm::vec3 centre = world_of(x, y, depth);
        const glm::vec3 u{0.0f, 0.01f, 0.0f};
        const glm::vec3 w{0.0f, 0.0f, 0.01f};
        triangle(centre + u, centre + w, centre - u - w);
    }
    void start_second_chunk() {
        Chunk first;
        first.first_index = 0;
        first.index_count = static_cast<std::uint32_t>(scene.indices.size());
        scene.chunks.push_back(first);
        in_second = true;
        second_chunk_first_vertex = scene.vertices.size();
    }
    Scene finish() {
        Chunk second;
        second.first_index = static_cast<std::uint32_t>(scene.indices.size());
        second.index_count = static_cast<std::uint32_t>(second_chunk_indices.size());
        second.vertex_offset = static_cast<std::int32_t>(second_chunk_first_vertex);
        scene.indices.insert(scene.indices.end(), second_chunk_indices.begin(),
                             second_chunk_indices.end());
        scene.chunks.push_back(second);
        return scene;
    }
};

// Six triangles in view at depths 1, 2, 4, 9, 20 and 35 m; seven out of it.
Scene hand_built_scene() {
    SceneBuilder b;
    b.at(0.0, 0.0, 1.0);
    b.at(-1.3, 1.4, 2.0);  // near the upper left corner: tangents -0.65 and 0.7
    b.at(4.9, -5.8, 4.0);  // tangents 1.225 and -1.45, just inside right and down
    // Out of view: behind the eye, nearer than near, beyond far, left of, right of, above and
    // below the frustum.
    b.at(0.0, 0.0, -3.0);
    b.at(0.0, 0.0, 0.05);
    b.at(0.0, 0.0, 2000.0);
    b.at(-1.45 * 5.0, 0.0, 5.0);
    b.at(1.30 * 6.0, 0.0, 6.0);
    b.start_second_chunk();
    b.at(2.0, 3.0, 9.0);
    b.at(0.0, 1.50 * 7.0, 7.0);
    b.at(0.0, -1.50 * 8.0, 8.0);
    b.at(-10.0, -12.0, 20.0);
    // A large triangle with one corner in view at depth 35 and its centroid too (counted), and
    // one with a corner in view but its centroid left of the frustum (not counted).
    b.triangle(world_of(0.0, 0.0, 35.0), world_of(-30.0, 0.0, 35.0), world_of(30.0, 1.0, 35.0));
    b.triangle(world_of(0.0, 0.0, 12.0), world_of(-40.0, 0.0, 12.0), world_of(-40.0, 1.0, 12.0));
    return b.finish();
}

DepthProfileView turned_view() {
    DepthProfileView view;
    view.eye = turned_eye();
    view.tangents = vive_left();
    view.near = 0.1;
    view.far = 1000.0;
    return view;
}

TEST(DepthProfile, FractionsOfTheTrianglesInViewNearerThanEachDistance) {
    const Scene scene = hand_built_scene();
    ASSERT_EQ(scene.triangle_count(), 14u);
    const std::vector<double> distances = {0.5, 1.5, 3.0, 10.0, 30.0, 50.0};
    const PrimitiveDepthProfile profile = primitive_depth_profile(scene, turned_view(), distances);
    EXPECT_EQ(profile.triangles_in_view, 6u);
    // In view at 1, 2, 4, 9, 20, 35 m.
    const std::vector<double> expected = {0.0, 1.0 / 6, 2.0 / 6, 4.0 / 6, 5.0 / 6, 1.0};
    ASSERT_EQ(profile.fraction_nearer.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_DOUBLE_EQ(profile.fraction_nearer[i], expected[i]) << "m = " << distances[i];
}

TEST(DepthProfile, OrientationMatters) {
    // From the same place looking down world -z (yaw 0), the eye-frame point (x, y, -d) of the
    // turned eye lies at depth x, across -d / x and up y / x: only the triangles placed at
    // (4.9, -5.8, -4) and (7.8, 0, -6) are in view, at depths 4.9 and 7.8 m.
    const Scene scene = hand_built_scene();
    DepthProfileView view = turned_view();
    view.eye.orientation = rig::orientation_from_yaw_pitch(0.0, 0.0);
    const std::vector<double> distances = {4.0, 5.0, 10.0};
    const PrimitiveDepthProfile profile = primitive_depth_profile(scene, view, distances);
    EXPECT_EQ(profile.triangles_in_view, 2u);
    ASSERT_EQ(profile.fraction_nearer.size(), 3u);
    EXPECT_DOUBLE_EQ(profile.fraction_nearer[0], 0.0);
    EXPECT_DOUBLE_EQ(profile.fraction_nearer[1], 0.5);
    EXPECT_DOUBLE_EQ(profile.fraction_nearer[2], 1.0);
}

TEST(DepthProfile, NothingInViewGivesNaN) {
    const Scene scene = hand_built_scene();
    DepthProfileView view = turned_view();
    view.eye.position.z += 5000.0;  // far off to the side: every triangle is left of the view
    const std::vector<double> distances = {1.0, 100.0};
    const PrimitiveDepthProfile profile = primitive_depth_profile(scene, view, distances);
    EXPECT_EQ(profile.triangles_in_view, 0u);
    ASSERT_EQ(profile.fraction_nearer.size(), 2u);
    EXPECT_TRUE(std::isnan(profile.fraction_nearer[0]));
    EXPECT_TRUE(std::isnan(profile.fraction_nearer[1]));
}

TEST(DepthProfile, EyePoseShiftsAlongTheHeadsRightAxis) {
    rig::Pose head = turned_eye();
    const rig::Pose left = eye_pose(head, {-0.032, 0.0, 0.0});
    // Head +x is world -z (see turned_eye): the left eye sits 3.2 cm towards world +z.
    EXPECT_NEAR(left.position.x, kEye.x, 1e-12);
    EXPECT_NEAR(left.position.y, kEye.y, 1e-12);
    EXPECT_NEAR(left.position.z, kEye.z + 0.032, 1e-12);
    EXPECT_EQ(left.orientation, head.orientation);
}

TEST(DepthProfile, PixelFractions) {
    const float sky = 1.0e30f;
    const std::vector<float> depth = {0.5f, 1.0f, 2.0f, sky, 7.9f, 8.0f, sky, 30.0f};
    const std::vector<double> distances = {0.25, 1.0, 1.6, 8.0, 39.5};
    const std::vector<double> fractions = pixel_fraction_nearer(depth, distances);
    // Strictly nearer than m; the sky is in the denominator and beyond every m.
    const std::vector<double> expected = {0.0, 1.0 / 8, 2.0 / 8, 4.0 / 8, 6.0 / 8};
    ASSERT_EQ(fractions.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_DOUBLE_EQ(fractions[i], expected[i]) << "m = " << distances[i];

    const std::vector<float> none;
    const std::vector<double> empty = pixel_fraction_nearer(none, distances);
    ASSERT_EQ(empty.size(), distances.size());
    for (const double f : empty) EXPECT_TRUE(std::isnan(f));
}

}  // namespace
}  // namespace monoplane::scenes
