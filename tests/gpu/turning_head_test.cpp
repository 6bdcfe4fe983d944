// A turning head compiles nothing (issue 29): after warm-up, frames whose views keep turning
// create no pipeline and make the driver compile no shader variant. The driver's compiles are
// counted where they can be (profile::driver_compiles: lavapipe, CI's device); keeping a
// per-frame value in a uniform buffer that a shader stores and reuses made lavapipe compile a
// new culling variant every frame, ~0.7 s each.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "renderer/profile/driver_compiles.h"
#include "renderer/vk/pipeline.h"
#include "rig/pose_path.h"
#include "scenes/generate.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/profile_inputs.h"

namespace monoplane {
namespace {

class TurningHead : public testing::GpuTest {
  protected:
    // Frames along "turn" (yaw back and forth at 30 degrees a second) and "sway", every pose new:
    // a driver that keys variants on view-dependent values compiles on each of them.
    void render_along_paths(modes::ModeRenderer& renderer, const rig::Pose& start,
                            double time_offset, int frames) {
        const rig::PosePath turn = *rig::builtin_pose_path("turn");
        const rig::PosePath sway = *rig::builtin_pose_path("sway");
        for (int i = 0; i < frames; ++i) {
            const double t = time_offset + i / 9.0;
            const rig::PosePath& path = i % 2 == 0 ? turn : sway;
            renderer.submit_frame(testing::profile_inputs(vive_, rig::pose_along(path, start, t)));
            renderer.take_completed();
        }
        renderer.finish_frames();
    }

    void expect_no_compiles_after_warmup(plan::Mode mode, const modes::RendererOptions& options) {
        const scenes::Scene scene =
            scenes::generate_scene(scenes::SceneId::Landscape, scenes::Detail::Test, 5);
        const rig::Pose start = scene.viewpoints.front().head;
        modes::ModeRenderer renderer(ctx(), scene, mode, vk::Extent2D(96, 108), options);
        // Warm-up: the paths' extremes and a few poses between, none of them repeated below.
        render_along_paths(renderer, start, 0.05, 10);

        const std::uint64_t pipelines_before = vk_core::pipelines_created();
        const profile::DriverCompiles before = profile::driver_compiles();
        render_along_paths(renderer, start, 0.0, 16);
        const profile::DriverCompiles during =
            profile::compiles_between(before, profile::driver_compiles());
        EXPECT_EQ(vk_core::pipelines_created() - pipelines_before, 0u);
        if (ctx().device_info().name.find("llvmpipe") != std::string::npos) {
            // The probe must be live on the device CI runs, or this test would prove nothing.
            ASSERT_TRUE(during.measurable) << "lavapipe's LLVM compiles are not being counted";
        }
        EXPECT_EQ(during.modules, 0u) << during.seconds << " s of driver compiles while turning";
    }

    hmd::HmdProfile vive_ = hmd::load_hmd_profile("vive").value_or_throw();
};

TEST_F(TurningHead, StereoCompilesNothingAfterWarmup) {
    expect_no_compiles_after_warmup(plan::Mode::kStereo, {});
}

TEST_F(TurningHead, HybridWithTaaAndStereoSsaoCompilesNothingAfterWarmup) {
    modes::RendererOptions options;
    options.anti_aliasing = plan::AntiAliasing::kTaa;
    options.ssao = passes::SsaoVariant::kStereoConsistent;
    expect_no_compiles_after_warmup(plan::Mode::kHybrid, options);
}

TEST_F(TurningHead, TheProbeCountsTheDriversCompilesOfANewPipeline) {
    // A renderer built now creates pipelines; on an LLVM-based driver each is compiled, so the
    // probe that the tests above rely on must see them.
    const scenes::Scene scene =
        scenes::generate_scene(scenes::SceneId::Beams, scenes::Detail::Test, 5);
    const std::uint64_t pipelines_before = vk_core::pipelines_created();
    const profile::DriverCompiles before = profile::driver_compiles();
    modes::ModeRenderer renderer(ctx(), scene, plan::Mode::kStereo, vk::Extent2D(32, 32), {});
    renderer.render_frame(testing::profile_inputs(vive_, scene.viewpoints.front().head));
    const profile::DriverCompiles during =
        profile::compiles_between(before, profile::driver_compiles());
    EXPECT_GT(vk_core::pipelines_created() - pipelines_before, 3u);
    if (!during.measurable) GTEST_SKIP() << "the driver does not compile through LLVM";
    // lavapipe compiles a stage when it is first used, so a pipeline the frame did not use may
    // still be waiting: at least one compile, and time spent on it.
    EXPECT_GT(during.modules, 0u);
    EXPECT_GT(during.seconds, 0.0);
}

}  // namespace
}  // namespace monoplane
