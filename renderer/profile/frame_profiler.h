// GPU timestamps around each pass and pipeline-statistics queries around each view's draws.
// Usage per frame: begin_frame(cmd); {begin_pass; ...; end_pass}*; {begin_view; ...; end_view}*;
// submit and wait; then collect().
#pragma once

#include <string>
#include <vector>

#include "renderer/profile/frame_stats.h"
#include "renderer/vk/context.h"

namespace monoplane::profile {

class FrameProfiler {
  public:
    static constexpr std::uint32_t kMaxPasses = 64;
    static constexpr std::uint32_t kMaxViews = 8;

    explicit FrameProfiler(const vk_core::Context& ctx);

    // Resets the query pools; call first in a frame's command buffer.
    void begin_frame(const vk::raii::CommandBuffer& cmd);
    void begin_pass(const vk::raii::CommandBuffer& cmd, const std::string& name);
    void end_pass(const vk::raii::CommandBuffer& cmd);
    // Statistics are gathered only if the device supports pipelineStatisticsQuery.
    void begin_view(const vk::raii::CommandBuffer& cmd, const std::string& view);
    void end_view(const vk::raii::CommandBuffer& cmd);

    // May be called once the frame's submission has completed.
    FrameStats collect() const;

  private:
    const vk_core::Context& ctx_;
    vk::raii::QueryPool timestamps_{nullptr};
    vk::raii::QueryPool statistics_{nullptr};
    // The ViewStatistics field of each value a statistics query returns, in order.
    std::vector<std::uint64_t ViewStatistics::*> counter_fields_;
    std::vector<std::string> pass_names_;
    std::vector<std::string> view_names_;
    bool pass_open_ = false;
    bool view_open_ = false;
};

}  // namespace monoplane::profile
