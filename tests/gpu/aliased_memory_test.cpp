// Two transient images bound to one memory (vk_core::Image's shared-memory constructor), their
// uses ordered by the render graph's executor (graph::compile's aliasing): each frame clears a
// and copies it to a buffer, then clears b, which takes the memory over, and copies it. Two frames
// are recorded into one command buffer, so the second frame's a takes the memory back from the
// first frame's b with nothing but the graph's barriers between them. With every barrier the
// copies read what was cleared and the synchronisation validation layer reports nothing; without
// the aliasing barriers (their source scopes dropped, their layout transitions kept) it reports
// the write after read on the shared memory.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "renderer/executor/graph_executor.h"
#include "renderer/plan/frame_plan.h"
#include "renderer/plan/pass_steps.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/image.h"
#include "tests/gpu/gpu_test.h"

namespace monoplane {
namespace {

constexpr vk::Extent2D kSize{16, 16};
constexpr vk::DeviceSize kBytes = vk::DeviceSize{kSize.width} * kSize.height * 4;

struct Outcome {
    std::size_t messages = 0;
    std::string text;
    std::uint32_t a = 0;  // the first texel each copy read, as R8G8B8A8 bytes
    std::uint32_t b = 0;
    bool same_memory = false;
};

// Two frames of clear-a, copy-a, clear-b, copy-b; the texels of the second.
Outcome run(bool drop_aliasing_barriers) {
    const std::unique_ptr<vk_core::Context> ctx = testing::make_validated_context();
    if (!ctx) return {};
    const vk_core::ImageDesc desc{
        kSize, vk::Format::eR8G8B8A8Unorm,
        vk::ImageUsageFlagBits::eTransferDst | vk::ImageUsageFlagBits::eTransferSrc |
            vk::ImageUsageFlagBits::eSampled};  // sampled: an image view needs a view usage
    const vk::MemoryRequirements needs = vk_core::Image::memory_requirements(*ctx, desc);
    const vk_core::DeviceMemory shared =
        vk_core::allocate_memory(*ctx, needs, vk::MemoryPropertyFlagBits::eDeviceLocal);
    const vk_core::Image a(*ctx, desc, shared);
    const vk_core::Image b(*ctx, desc, shared);
    const vk_core::Buffer read_a(*ctx, kBytes, vk::BufferUsageFlagBits::eTransferDst,
                                 vk_core::MemoryUse::kHostVisible);
    const vk_core::Buffer read_b(*ctx, kBytes, vk::BufferUsageFlagBits::eTransferDst,
                                 vk_core::MemoryUse::kHostVisible);

    plan::FramePlan frame;
    plan::PlanResources r(frame);
    const graph::ImageHandle ha = r.image(plan::ViewId::kLeft, plan::ImageRole::kHdr);
    const graph::ImageHandle hb = r.image(plan::ViewId::kRight, plan::ImageRole::kHdr);
    const graph::BufferHandle ba = r.buffer(plan::ViewId::kLeft, plan::BufferRole::kReadback);
    const graph::BufferHandle bb = r.buffer(plan::ViewId::kRight, plan::BufferRole::kReadback);
    const auto add = [&](const std::string& name, std::vector<graph::ResourceUse> uses) {
        plan::PlannedPass& pass = frame.passes.emplace_back();
        pass.kind = plan::PassKind::kReadback;
        pass.name = name;
        pass.steps.push_back({"step", std::move(uses), false});
    };
    add("clear-a", {{ha.index, graph::Use::kTransferDst}});
    add("copy-a", {{ha.index, graph::Use::kTransferSrc}, {ba.index, graph::Use::kTransferDst}});
    add("clear-b", {{hb.index, graph::Use::kTransferDst}});
    add("copy-b", {{hb.index, graph::Use::kTransferSrc}, {bb.index, graph::Use::kTransferDst}});
    frame.exports = {{ba.index, graph::Use::kHostRead}, {bb.index, graph::Use::kHostRead}};
    std::vector<executor::BoundResource> bindings(frame.resources.size());
    bindings[ha.index].images = {a.range()};
    bindings[hb.index].images = {b.range()};

    executor::GraphExecutor executor;
    if (drop_aliasing_barriers) {
        executor.drop_barriers_for_test(
            [](const graph::Barrier& barrier, const plan::FramePlan&) { return barrier.aliasing; });
    }
    const vk::ImageSubresourceRange all(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1);
    const vk::BufferImageCopy region(0, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1}, {},
                                     vk::Extent3D(kSize, 1));
    ctx->submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
        for (float frame_value : {0.25f, 0.5f}) {
            executor.begin_frame(frame, bindings);
            const auto pass = [&](std::size_t p, const auto& record) {
                executor.begin_pass(cmd, p);
                record();
                executor.end_pass();
            };
            pass(0, [&] {
                cmd.clearColorImage(a.handle(), vk::ImageLayout::eTransferDstOptimal,
                                    vk::ClearColorValue(frame_value, 0.0f, 0.0f, 1.0f), all);
            });
            pass(1, [&] {
                cmd.copyImageToBuffer(a.handle(), vk::ImageLayout::eTransferSrcOptimal,
                                      read_a.handle(), region);
            });
            pass(2, [&] {
                cmd.clearColorImage(b.handle(), vk::ImageLayout::eTransferDstOptimal,
                                    vk::ClearColorValue(0.0f, frame_value, 0.0f, 1.0f), all);
            });
            pass(3, [&] {
                cmd.copyImageToBuffer(b.handle(), vk::ImageLayout::eTransferSrcOptimal,
                                      read_b.handle(), region);
            });
            executor.end_frame(cmd);
        }
    });
    ctx->device().waitIdle();
    Outcome outcome;
    outcome.messages = ctx->validation_messages().count();
    for (const std::string& m : ctx->validation_messages().first_messages()) {
        outcome.text += m + "\n";
    }
    std::memcpy(&outcome.a, read_a.mapped(), sizeof outcome.a);
    std::memcpy(&outcome.b, read_b.mapped(), sizeof outcome.b);
    outcome.same_memory = a.memory() == b.memory() && a.range().shared_memory == *shared;
    return outcome;
}

// R8G8B8A8 of (r, g, 0, 1), as the host reads the copy's four bytes.
std::uint32_t texel(std::uint8_t red, std::uint8_t green) {
    const std::uint8_t bytes[4] = {red, green, 0, 255};
    std::uint32_t value = 0;
    std::memcpy(&value, bytes, sizeof value);
    return value;
}

TEST(AliasedMemory, EachImageReadsWhatWasWrittenAndTheLayerReportsNothing) {
    const Outcome outcome = run(false);
    EXPECT_TRUE(outcome.same_memory);
    EXPECT_EQ(outcome.messages, 0u) << outcome.text;
    EXPECT_EQ(outcome.a, texel(128, 0));  // 0.5 in UNORM8, rounded to nearest
    EXPECT_EQ(outcome.b, texel(0, 128));
}

TEST(AliasedMemory, WithoutTheAliasingBarriersTheLayerReportsTheHazard) {
    const Outcome outcome = run(true);
    EXPECT_GT(outcome.messages, 0u);
    EXPECT_NE(outcome.text.find("SYNC-HAZARD-WRITE-AFTER-READ"), std::string::npos) << outcome.text;
}

}  // namespace
}  // namespace monoplane
