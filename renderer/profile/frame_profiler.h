// GPU timestamps around each pass and pipeline-statistics queries around each view's draws.
// Usage per frame: begin_frame(cmd, slot); {begin_pass; ...; end_pass}*; {begin_view; ...;
// end_view}*; submit; once that submission has completed, collect(slot). Each frame-in-flight
// slot (vk_core::FrameRing) has its own query pools, so frame n+1 may be recorded before frame n
// is collected.
#pragma once

#include <string>
#include <vector>

#include "renderer/profile/frame_stats.h"
#include "renderer/vk/context.h"
#include "renderer/vk/frame_ring.h"

namespace monoplane::profile {

class FrameProfiler {
  public:
    static constexpr std::uint32_t kMaxPasses = 64;
    static constexpr std::uint32_t kMaxViews = 8;

    explicit FrameProfiler(const vk_core::Context& ctx,
                           std::uint32_t slots = vk_core::FrameRing::kFramesInFlight);

    // Resets the slot's query pools and records into them until the next begin_frame; call first
    // in a frame's command buffer.
    void begin_frame(const vk::raii::CommandBuffer& cmd, std::uint32_t slot = 0);
    // The pass's name and its kind and view (PassTime's).
    void begin_pass(const vk::raii::CommandBuffer& cmd, const std::string& name,
                    plan::PassKind kind, plan::ViewId view);
    void end_pass(const vk::raii::CommandBuffer& cmd);
    // Statistics are gathered only if the device supports pipelineStatisticsQuery.
    // The scope's name and the pass it counts (ViewStatistics's).
    void begin_view(const vk::raii::CommandBuffer& cmd, const std::string& view,
                    plan::PassKind pass_kind, plan::ViewId pass_view);
    void end_view(const vk::raii::CommandBuffer& cmd);

    // May be called once the submission of the slot's last frame has completed.
    FrameStats collect(std::uint32_t slot = 0) const;

  private:
    struct Slot {
        vk::raii::QueryPool timestamps{nullptr};
        vk::raii::QueryPool statistics{nullptr};
        std::vector<PassTime> passes;       // named, times to come
        std::vector<ViewStatistics> views;  // named, counters to come
    };
    const vk_core::Context& ctx_;
    std::vector<Slot> slots_;
    Slot* recording_ = nullptr;  // the slot of the frame being recorded
    // The ViewStatistics field of each value a statistics query returns, in order.
    std::vector<std::uint64_t ViewStatistics::*> counter_fields_;
    bool pass_open_ = false;
    bool view_open_ = false;
};

}  // namespace monoplane::profile
