// The renderer's transient images in shared memory (renderer/modes/transient_memory.h): in
// two-pass stereo one eye's depth shares memory with an image of the other eye, in hybrid C's
// depth with C's display image. Frames submitted back to back (frames in flight) compile barriers
// that hand the memory from one image to the next, leave the synchronisation validation layer
// silent, and draw the images of the single-pass forms, whose layered images share nothing.
//
// That the layer would see those barriers missing is shown by aliased_memory_test, on copies and
// clears recorded into one command buffer: here the images that share memory are written as
// attachments of dynamic rendering, which the layer of Debian 12 (1.3.239) does not seem to track,
// and the frames that would show the rest are separate submissions (dropping the barriers here was
// tried: the layer stayed silent).
#include <gtest/gtest.h>

#include <string>

#include "renderer/modes/mode_renderer.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/hybrid_test_scenes.h"

namespace monoplane {
namespace {

struct Rendered {
    std::size_t messages = 0;
    std::size_t aliasing_barriers = 0;  // compiled, recorded or dropped
    std::string text;
    modes::RgbaImage left;
    modes::RgbaImage right;
};

// Three frames in flight, then one waited for; the last frame's images.
Rendered render(plan::Mode mode, plan::StereoPass stereo_pass) {
    const std::unique_ptr<vk_core::Context> ctx = testing::make_validated_context();
    if (!ctx) return {};
    const scenes::Scene scene = testing::marker_scene(glm::vec3(0.3f, 1.8f, -12.0f), 0.5f);
    modes::RendererOptions options;
    options.shadow.resolution = 256;
    options.stereo_pass = stereo_pass;
    modes::ModeRenderer renderer(*ctx, scene, mode, {96, 96}, options);
    // Counts the barriers that hand shared memory on, dropping none.
    std::size_t aliasing_barriers = 0;
    renderer.drop_barriers_for_test([&](const graph::Barrier& b, const plan::FramePlan&) {
        if (b.aliasing) ++aliasing_barriers;
        return false;
    });
    modes::FrameInputs inputs;
    inputs.views.head.position = {0.0, 1.7, 0.0};
    inputs.views.left = inputs.views.right = rig::Tangents{-1.0, 1.0, -1.0, 1.0};
    inputs.mono_plane = 4.0;
    for (int frame = 0; frame < 3; ++frame) {
        inputs.frame_index = static_cast<std::uint64_t>(frame);
        renderer.submit_frame(inputs);
    }
    renderer.finish_frames();
    renderer.render_frame(inputs);
    ctx->device().waitIdle();
    Rendered rendered{ctx->validation_messages().count(),
                      aliasing_barriers,
                      {},
                      renderer.eye_image(modes::Eye::kLeft),
                      renderer.eye_image(modes::Eye::kRight)};
    for (const std::string& m : ctx->validation_messages().first_messages()) {
        rendered.text += m + "\n";
    }
    return rendered;
}

TEST(TransientMemory, StereoSharesTheEyesMemoryWithoutAHazardAndDrawsAsSinglePass) {
    const Rendered two = render(plan::Mode::kStereo, plan::StereoPass::kTwoPasses);
    EXPECT_EQ(two.messages, 0u) << two.text;
    EXPECT_GT(two.aliasing_barriers, 0u);
    const Rendered instanced = render(plan::Mode::kStereo, plan::StereoPass::kInstanced);
    EXPECT_EQ(instanced.messages, 0u) << instanced.text;
    EXPECT_EQ(instanced.aliasing_barriers, 0u);  // layered images share nothing
    EXPECT_TRUE(two.left.pixels == instanced.left.pixels);
    EXPECT_TRUE(two.right.pixels == instanced.right.pixels);
}

TEST(TransientMemory, HybridSharesCsMemoryWithoutAHazard) {
    const Rendered hybrid = render(plan::Mode::kHybrid, plan::StereoPass::kTwoPasses);
    EXPECT_EQ(hybrid.messages, 0u) << hybrid.text;
    EXPECT_GT(hybrid.aliasing_barriers, 0u);
}

}  // namespace
}  // namespace monoplane
