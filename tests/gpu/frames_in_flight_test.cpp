// Frames in flight (vk_core::FrameRing, FrameUploads, ModeRenderer::submit_frame): frames
// submitted back to back, without waiting, each read their own constants and report their own
// statistics, and the last one's images equal those of the same frames rendered one at a time.
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "renderer/vk/frame_ring.h"
#include "renderer/vk/frame_uploads.h"
#include "scenes/generate.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/profile_inputs.h"

namespace monoplane {
namespace {

class FramesInFlight : public testing::GpuTest {};

// The head turned about the vertical by `degrees` and moved `forward` metres along its view.
rig::Pose turned(const rig::Pose& head, double degrees, double forward = 0.0) {
    rig::Pose pose = head;
    pose.orientation =
        glm::angleAxis(glm::radians(degrees), glm::dvec3(0.0, 1.0, 0.0)) * head.orientation;
    pose.position += forward * (pose.orientation * glm::dvec3(0.0, 0.0, -1.0));
    return pose;
}

// What a frame's statistics say it drew, per view: chunks, primitives, fragments.
struct ViewWork {
    std::string view;
    std::uint32_t draws;
    std::uint64_t primitives;
    std::uint64_t fragments;
    bool operator==(const ViewWork&) const = default;
};

std::vector<ViewWork> work(const profile::FrameStats& stats) {
    std::vector<ViewWork> views;
    for (const profile::ViewStatistics& v : stats.views) {
        views.push_back({v.view, v.draws, v.clipping_invocations, v.fragment_invocations});
    }
    return views;
}

TEST_F(FramesInFlight, EachFrameDrawsWithItsOwnConstantsAndEndsLikeWaitedFrames) {
    const scenes::Scene scene =
        scenes::generate_scene(scenes::SceneId::Spheres, scenes::Detail::Test, 3);
    const hmd::HmdProfile vive = hmd::load_hmd_profile("vive").value_or_throw();
    modes::RendererOptions options;
    options.shadow.resolution = 1024;
    const vk::Extent2D extent(168, 189);
    const rig::Pose head = scene.viewpoints.front().head;
    // Poses far enough apart that consecutive frames draw different chunks: a frame that read
    // its successor's constants would report the successor's work.
    const std::vector<rig::Pose> poses = {head, turned(head, 50.0), turned(head, -70.0),
                                          turned(head, 0.0, 6.0), turned(head, 120.0)};

    modes::ModeRenderer waited(ctx(), scene, plan::Mode::kHybrid, extent, options);
    std::vector<std::vector<ViewWork>> expected;
    for (const rig::Pose& pose : poses) {
        expected.push_back(work(waited.render_frame(testing::profile_inputs(vive, pose, 8.0))));
    }
    int different = 0;
    for (std::size_t i = 1; i < expected.size(); ++i) different += expected[i] != expected[i - 1];
    ASSERT_EQ(different, static_cast<int>(poses.size()) - 1) << "the poses must differ in work";

    modes::ModeRenderer pipelined(ctx(), scene, plan::Mode::kHybrid, extent, options);
    std::vector<profile::FrameStats> stats;
    for (const rig::Pose& pose : poses) {
        pipelined.submit_frame(testing::profile_inputs(vive, pose, 8.0));
        for (profile::FrameStats& s : pipelined.take_completed()) stats.push_back(std::move(s));
    }
    // With two frames in flight, at most the frames two before have completed on submit.
    EXPECT_LE(stats.size(), poses.size() - 1);
    for (profile::FrameStats& s : pipelined.finish_frames()) stats.push_back(std::move(s));
    ASSERT_EQ(stats.size(), poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i) {
        EXPECT_EQ(work(stats[i]), expected[i]) << "frame " << i;
        EXPECT_GT(stats[i].gpu_frame_ms, 0.0) << "frame " << i;
    }
    for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
        EXPECT_EQ(pipelined.eye_image(eye).pixels, waited.eye_image(eye).pixels)
            << modes::eye_name(eye);
    }
    EXPECT_TRUE(pipelined.take_completed().empty());
}

TEST_F(FramesInFlight, UploadsLargerThanOneUpdateArriveWhole) {
    // 70,000 words: more than vkCmdUpdateBuffer's 65,536 bytes, so several updates.
    std::vector<std::uint32_t> words(70000);
    std::iota(words.begin(), words.end(), 17u);
    const vk::DeviceSize bytes = words.size() * sizeof(std::uint32_t);
    const vk_core::Buffer target(ctx(), bytes, vk::BufferUsageFlagBits::eTransferSrc,
                                 vk_core::MemoryUse::kDeviceLocal);
    const vk_core::Buffer host(ctx(), bytes, vk::BufferUsageFlagBits::eTransferDst,
                               vk_core::MemoryUse::kHostVisible);
    vk_core::FrameUploads uploads;
    uploads.stage(target, words.data(), bytes);
    // A later stage of a range wins, as a second write would.
    const std::uint32_t replaced[2] = {7u, 9u};
    uploads.stage(target, replaced, sizeof(replaced), 4 * 1000);
    EXPECT_FALSE(uploads.empty());
    vk_core::FrameRing ring(ctx());
    const std::uint32_t slot = ring.begin();
    const vk::raii::CommandBuffer& cmd = ring.commands(slot);
    uploads.record(cmd);
    EXPECT_TRUE(uploads.empty());
    const vk::MemoryBarrier2 readable(
        vk::PipelineStageFlagBits2::eTransfer, vk::AccessFlagBits2::eTransferWrite,
        vk::PipelineStageFlagBits2::eTransfer, vk::AccessFlagBits2::eTransferRead);
    cmd.pipelineBarrier2(vk::DependencyInfo({}, readable));
    cmd.copyBuffer(target.handle(), host.handle(), vk::BufferCopy(0, 0, bytes));
    const vk::MemoryBarrier2 to_host(
        vk::PipelineStageFlagBits2::eTransfer, vk::AccessFlagBits2::eTransferWrite,
        vk::PipelineStageFlagBits2::eHost, vk::AccessFlagBits2::eHostRead);
    cmd.pipelineBarrier2(vk::DependencyInfo({}, to_host));
    ring.submit(slot);
    EXPECT_TRUE(ring.in_flight(slot));
    ring.wait(slot);
    EXPECT_FALSE(ring.in_flight(slot));
    const auto* read = reinterpret_cast<const std::uint32_t*>(host.mapped());
    EXPECT_EQ(read[0], 17u);
    EXPECT_EQ(read[999], 17u + 999u);
    EXPECT_EQ(read[1000], 7u);
    EXPECT_EQ(read[1001], 9u);
    EXPECT_EQ(read[1002], 17u + 1002u);
    EXPECT_EQ(read[16384], 17u + 16384u);  // the first word of the second update
    EXPECT_EQ(read[69999], 17u + 69999u);
}

TEST_F(FramesInFlight, UploadsRefuseRangesVkCmdUpdateBufferCannotWrite) {
    const vk_core::Buffer target(ctx(), 64, vk::BufferUsageFlagBits::eUniformBuffer,
                                 vk_core::MemoryUse::kDeviceLocal);
    vk_core::FrameUploads uploads;
    const std::uint32_t data[4] = {};
    // A programming error: the process stops (a death test's child) and says where.
    EXPECT_DEATH(uploads.stage(target, data, 6), "programming error.*bytes % 4 == 0");  // not words
    EXPECT_DEATH(uploads.stage(target, data, 4, 2), "programming error.*offset % 4 == 0");
    EXPECT_DEATH(uploads.stage(target, data, 16, 56), "programming error.*target.size");
    EXPECT_TRUE(uploads.empty());
}

}  // namespace
}  // namespace monoplane
