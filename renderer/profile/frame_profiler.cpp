#include "renderer/profile/frame_profiler.h"

#include <array>
#include <cassert>

namespace monoplane::profile {
namespace {

using Stat = vk::QueryPipelineStatisticFlagBits;

// The counters gathered, in the order of their flags' bits: the order a query's results come in.
struct Counter {
    Stat flag;
    std::uint64_t ViewStatistics::*field;
    bool needs_geometry_shader;  // the flag requires the geometryShader feature
};
constexpr std::array<Counter, 7> kCounters = {{
    {Stat::eInputAssemblyPrimitives, &ViewStatistics::input_primitives, false},
    {Stat::eVertexShaderInvocations, &ViewStatistics::vertex_invocations, false},
    {Stat::eGeometryShaderInvocations, &ViewStatistics::geometry_invocations, true},
    {Stat::eGeometryShaderPrimitives, &ViewStatistics::geometry_primitives, true},
    {Stat::eClippingInvocations, &ViewStatistics::clipping_invocations, false},
    {Stat::eClippingPrimitives, &ViewStatistics::clipping_primitives, false},
    {Stat::eFragmentShaderInvocations, &ViewStatistics::fragment_invocations, false},
}};

}  // namespace

FrameProfiler::FrameProfiler(const vk_core::Context& ctx) : ctx_(ctx) {
    timestamps_ = vk::raii::QueryPool(
        ctx.device(), vk::QueryPoolCreateInfo({}, vk::QueryType::eTimestamp, 2 * kMaxPasses));
    if (ctx.capabilities().pipeline_statistics) {
        vk::QueryPipelineStatisticFlags flags;
        for (const Counter& counter : kCounters) {
            if (counter.needs_geometry_shader && !ctx.capabilities().geometry_shader) continue;
            flags |= counter.flag;
            counter_fields_.push_back(counter.field);
        }
        statistics_ = vk::raii::QueryPool(
            ctx.device(),
            vk::QueryPoolCreateInfo({}, vk::QueryType::ePipelineStatistics, kMaxViews, flags));
    }
}

void FrameProfiler::begin_frame(const vk::raii::CommandBuffer& cmd) {
    pass_names_.clear();
    view_names_.clear();
    cmd.resetQueryPool(*timestamps_, 0, 2 * kMaxPasses);
    if (*statistics_) cmd.resetQueryPool(*statistics_, 0, kMaxViews);
}

void FrameProfiler::begin_pass(const vk::raii::CommandBuffer& cmd, const std::string& name) {
    assert(!pass_open_ && pass_names_.size() < kMaxPasses);
    const auto index = static_cast<std::uint32_t>(2 * pass_names_.size());
    cmd.writeTimestamp2(vk::PipelineStageFlagBits2::eTopOfPipe, *timestamps_, index);
    pass_names_.push_back(name);
    pass_open_ = true;
}

void FrameProfiler::end_pass(const vk::raii::CommandBuffer& cmd) {
    assert(pass_open_);
    const auto index = static_cast<std::uint32_t>(2 * pass_names_.size() - 1);
    cmd.writeTimestamp2(vk::PipelineStageFlagBits2::eBottomOfPipe, *timestamps_, index);
    pass_open_ = false;
}

void FrameProfiler::begin_view(const vk::raii::CommandBuffer& cmd, const std::string& view) {
    assert(!view_open_ && view_names_.size() < kMaxViews);
    view_names_.push_back(view);
    view_open_ = true;
    if (*statistics_)
        cmd.beginQuery(*statistics_, static_cast<std::uint32_t>(view_names_.size() - 1), {});
}

void FrameProfiler::end_view(const vk::raii::CommandBuffer& cmd) {
    assert(view_open_);
    view_open_ = false;
    if (*statistics_)
        cmd.endQuery(*statistics_, static_cast<std::uint32_t>(view_names_.size() - 1));
}

FrameStats FrameProfiler::collect() const {
    assert(!pass_open_ && !view_open_);
    FrameStats stats;
    if (!pass_names_.empty()) {
        const auto count = static_cast<std::uint32_t>(2 * pass_names_.size());
        const auto [result, ticks] = timestamps_.getResults<std::uint64_t>(
            0, count, count * sizeof(std::uint64_t), sizeof(std::uint64_t),
            vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
        assert(result == vk::Result::eSuccess);
        const std::uint32_t bits = ctx_.capabilities().timestamp_valid_bits;
        const std::uint64_t mask = bits >= 64 ? ~0ull : ((1ull << bits) - 1);
        const double ms_per_tick = ctx_.capabilities().timestamp_period_ns * 1e-6;
        auto elapsed_ms = [&](std::uint64_t begin, std::uint64_t end) {
            return static_cast<double>((end - begin) & mask) * ms_per_tick;
        };
        for (std::size_t i = 0; i < pass_names_.size(); ++i) {
            stats.passes.push_back({pass_names_[i], elapsed_ms(ticks[2 * i], ticks[2 * i + 1])});
        }
        stats.gpu_frame_ms = elapsed_ms(ticks.front(), ticks.back());
    }
    if (*statistics_ && !view_names_.empty()) {
        const std::size_t per_view = counter_fields_.size();
        const auto count = static_cast<std::uint32_t>(view_names_.size());
        const std::size_t stride = per_view * sizeof(std::uint64_t);
        const auto [result, values] = statistics_.getResults<std::uint64_t>(
            0, count, count * stride, stride,
            vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
        assert(result == vk::Result::eSuccess);
        for (std::size_t i = 0; i < view_names_.size(); ++i) {
            ViewStatistics view;
            view.view = view_names_[i];
            for (std::size_t k = 0; k < per_view; ++k) {
                view.*counter_fields_[k] = values[i * per_view + k];
            }
            stats.views.push_back(std::move(view));
        }
    }
    return stats;
}

}  // namespace monoplane::profile
