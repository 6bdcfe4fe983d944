// Memory stays bounded however long frames run (issue 29): a renderer submitting thousands of
// frames back to back, as `bench` and a headset session do, with the head moving. Before the
// culling constants left their uniform buffer, lavapipe grew by about 0.55 MB a frame (1.1 GB
// over the 2,000 frames here); the bound below is 8 MiB, 4 KiB a frame, room for the allocator's
// arenas to settle and three orders of magnitude below that growth.
#include <gtest/gtest.h>

#include <cstdio>

#include "common/resident_memory.h"
#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "rig/pose_path.h"
#include "scenes/generate.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/profile_inputs.h"

namespace monoplane {
namespace {

class MemoryBound : public testing::GpuTest {};

TEST_F(MemoryBound, TwoThousandFramesInFlightKeepResidentMemoryBounded) {
    const scenes::Scene scene =
        scenes::generate_scene(scenes::SceneId::Beams, scenes::Detail::Test, 5);
    const hmd::HmdProfile vive = hmd::load_hmd_profile("vive").value_or_throw();
    modes::ModeRenderer renderer(ctx(), scene, plan::Mode::kHybrid, vk::Extent2D(32, 36), {});
    const rig::PosePath sway = *rig::builtin_pose_path("sway");
    const rig::Pose start = scene.viewpoints.front().head;
    int frame = 0;
    const auto run = [&](int frames) {
        for (int i = 0; i < frames; ++i, ++frame) {
            renderer.submit_frame(
                testing::profile_inputs(vive, rig::pose_along(sway, start, frame / 90.0)));
            renderer.take_completed();
        }
        renderer.finish_frames();
    };
    constexpr int kWarmup = 300;
    constexpr int kFrames = 2000;
    run(kWarmup);
    const std::optional<std::uint64_t> after_warmup = resident_bytes();
    ASSERT_TRUE(after_warmup) << "no /proc/self/statm";
    run(kFrames);
    const std::uint64_t at_end = resident_bytes().value();
    const double growth_mib =
        (static_cast<double>(at_end) - static_cast<double>(*after_warmup)) / (1024.0 * 1024.0);
    RecordProperty("growth_kib_per_frame", std::to_string(growth_mib * 1024.0 / kFrames));
    std::printf("resident memory: %.1f MiB after %d warm-up frames, %+.2f MiB over %d more\n",
                static_cast<double>(*after_warmup) / (1024.0 * 1024.0), kWarmup, growth_mib,
                kFrames);
    EXPECT_LT(growth_mib, 8.0);
}

}  // namespace
}  // namespace monoplane
