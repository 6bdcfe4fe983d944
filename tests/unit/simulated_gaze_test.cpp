// The simulated participant's error at gaze (app/commands/simulated_gaze.h): simxr's default gaze
// cast into the trial's scene from its seat. What one sample gives is checked against the
// geometry in gaze_point_test; here what follows from the model whatever the scene holds: a seed
// gives one value and another seed another, a nearer plane moves every point beyond it more (a
// point's error falls as m grows), and the error stays within the bound the gaze's spread allows.
#include <gtest/gtest.h>

#include <cmath>

#include "app/commands/simulated_gaze.h"
#include "hmd/profile.h"
#include "rig/angular_error.h"
#include "study/protocol.h"

namespace monoplane::app {
namespace {

study::Protocol protocol(const std::string& scene) {
    study::Protocol p;
    p.name = "gaze";
    p.scenes = {scene};
    p.mono_planes = {3.0, 8.0};
    p.render.detail = "test";
    return p;
}

study::ScheduledTrial trial(int index, double m) {
    study::ScheduledTrial t;
    t.index = index;
    t.scene = "beams";
    t.mono_plane = m;
    return t;
}

TEST(SimulatedGaze, OneValuePerSeedAndLargerForTheNearerPlane) {
    const hmd::HmdProfile vive = hmd::load_hmd_profile("vive").value_or_throw();
    const auto gaze = SimulatedGaze::build(protocol("beams"), vive).value_or_throw();
    int differing = 0;
    for (int i = 0; i < 20; ++i) {
        const double near_plane = gaze->error_at_gaze(trial(i, 3.0), 77);
        const double far_plane = gaze->error_at_gaze(trial(i, 8.0), 77);
        EXPECT_EQ(near_plane, gaze->error_at_gaze(trial(i, 3.0), 77));
        EXPECT_GT(near_plane, far_plane) << "trial " << i;
        EXPECT_GT(far_plane, 0.0) << "trial " << i;  // the beams run far beyond 8 m
        // Nothing is moved by more than atan(d / 2m) plus the field's widening: C's sky at the
        // field's edge, 36.7 arcmin straight ahead at 3 m for d = 64 mm, and well under twice
        // that anywhere within the 12 degrees the gaze keeps to.
        EXPECT_LT(near_plane, 2.0 * std::atan(0.032 / 3.0) * rig::kArcminPerRadian);
        differing += gaze->error_at_gaze(trial(i, 3.0), 78) != near_plane;
    }
    EXPECT_GE(differing, 18);  // another participant looks elsewhere
    // A trial whose m the simulation does not know (an adaptive trial not yet placed): none.
    EXPECT_EQ(gaze->error_at_gaze(trial(0, std::nan("")), 77), 0.0);
}

TEST(SimulatedGaze, AGltfSceneIsRefusedWithItsName) {
    const hmd::HmdProfile vive = hmd::load_hmd_profile("vive").value_or_throw();
    const auto refused = SimulatedGaze::build(protocol("models/tri.gltf"), vive);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().message,
              "scene 'models/tri.gltf' names a file: simulated gaze knows the built-in scenes "
              "only (beams, landscape, spheres)");
}

}  // namespace
}  // namespace monoplane::app
