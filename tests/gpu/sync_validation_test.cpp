// Every GPU and end-to-end test runs with the validation layer's synchronisation validation on
// (vk_core::ContextOptions::validation) and fails on any message. This shows that the layer would
// see what the render graph left out: with the compiled barrier removed that makes the culling
// pass's draw lists and counts (written by a compute shader) ready for the forward passes'
// indirect draws, it reports a read-after-write hazard; with every barrier, nothing.
#include <gtest/gtest.h>

#include <string>

#include "renderer/modes/mode_renderer.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/hybrid_test_scenes.h"

namespace monoplane {
namespace {

struct Reported {
    std::size_t count = 0;
    std::string messages;
};

// One hybrid frame and one more (frames in flight), with or without the draw lists' barrier.
Reported render_two_frames(bool drop_draw_list_barrier) {
    const std::unique_ptr<vk_core::Context> ctx = testing::make_validated_context();
    if (!ctx) return {};
    const scenes::Scene scene = testing::marker_scene(glm::vec3(0.3f, 1.8f, -12.0f), 0.5f);
    modes::RendererOptions options;
    options.shadow.resolution = 256;
    modes::ModeRenderer hybrid(*ctx, scene, plan::Mode::kHybrid, {96, 96}, options);
    if (drop_draw_list_barrier) {
        hybrid.drop_barriers_for_test([](const graph::Barrier& b, const plan::FramePlan& plan) {
            // Buffers take global memory barriers: both of the culling's buffers' go.
            return plan.resources[b.resource].kind == graph::ResourceKind::kBuffer &&
                   graph::covers(b.dst_access, graph::Access::kIndirectCommandRead);
        });
    }
    modes::FrameInputs inputs;
    inputs.views.head.position = {0.0, 1.7, 0.0};
    inputs.views.left = inputs.views.right = rig::Tangents{-1.0, 1.0, -1.0, 1.0};
    inputs.mono_plane = 4.0;
    for (int frame = 0; frame < 2; ++frame) hybrid.render_frame(inputs);
    ctx->device().waitIdle();
    Reported reported{ctx->validation_messages().count(), {}};
    for (const std::string& m : ctx->validation_messages().first_messages()) {
        reported.messages += m + "\n";
    }
    return reported;
}

TEST(SyncValidation, EveryCompiledBarrierInPlaceReportsNothing) {
    const Reported reported = render_two_frames(false);
    EXPECT_EQ(reported.count, 0u) << reported.messages;
}

TEST(SyncValidation, ARemovedBarrierIsReportedAsAReadAfterWriteHazard) {
    const Reported reported = render_two_frames(true);
    EXPECT_GT(reported.count, 0u);
    EXPECT_NE(reported.messages.find("SYNC-HAZARD-READ-AFTER-WRITE"), std::string::npos)
        << reported.messages;
    EXPECT_NE(reported.messages.find("INDIRECT_COMMAND_READ"), std::string::npos)
        << reported.messages;
}

}  // namespace
}  // namespace monoplane
