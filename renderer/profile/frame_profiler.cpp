#include "renderer/profile/frame_profiler.h"

#include <array>

#include "common/programming_error.h"

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

FrameProfiler::FrameProfiler(const vk_core::Context& ctx, std::uint32_t slots)
    : ctx_(ctx), slots_(slots) {
    vk::QueryPipelineStatisticFlags flags;
    if (ctx.capabilities().pipeline_statistics) {
        for (const Counter& counter : kCounters) {
            if (counter.needs_geometry_shader && !ctx.capabilities().geometry_shader) continue;
            flags |= counter.flag;
            counter_fields_.push_back(counter.field);
        }
    }
    for (Slot& slot : slots_) {
        slot.timestamps = vk::raii::QueryPool(
            ctx.device(), vk::QueryPoolCreateInfo({}, vk::QueryType::eTimestamp, 2 * kMaxPasses));
        if (!ctx.capabilities().pipeline_statistics) continue;
        slot.statistics = vk::raii::QueryPool(
            ctx.device(),
            vk::QueryPoolCreateInfo({}, vk::QueryType::ePipelineStatistics, kMaxViews, flags));
    }
}

void FrameProfiler::begin_frame(const vk::raii::CommandBuffer& cmd, std::uint32_t slot) {
    MONOPLANE_EXPECTS(slot < slots_.size());
    recording_ = &slots_[slot];
    recording_->passes.clear();
    recording_->views.clear();
    cmd.resetQueryPool(*recording_->timestamps, 0, 2 * kMaxPasses);
    if (*recording_->statistics) cmd.resetQueryPool(*recording_->statistics, 0, kMaxViews);
}

void FrameProfiler::begin_pass(const vk::raii::CommandBuffer& cmd, const std::string& name,
                               plan::PassKind kind, plan::ViewId view) {
    MONOPLANE_EXPECTS(recording_ && !pass_open_ && recording_->passes.size() < kMaxPasses);
    const auto index = static_cast<std::uint32_t>(2 * recording_->passes.size());
    cmd.writeTimestamp2(vk::PipelineStageFlagBits2::eTopOfPipe, *recording_->timestamps, index);
    recording_->passes.push_back({name, 0.0, kind, view});
    pass_open_ = true;
}

void FrameProfiler::end_pass(const vk::raii::CommandBuffer& cmd) {
    MONOPLANE_EXPECTS(pass_open_);
    const auto index = static_cast<std::uint32_t>(2 * recording_->passes.size() - 1);
    cmd.writeTimestamp2(vk::PipelineStageFlagBits2::eBottomOfPipe, *recording_->timestamps, index);
    pass_open_ = false;
}

void FrameProfiler::begin_view(const vk::raii::CommandBuffer& cmd, const std::string& view,
                               plan::PassKind pass_kind, plan::ViewId pass_view) {
    MONOPLANE_EXPECTS(recording_ && !view_open_ && recording_->views.size() < kMaxViews);
    ViewStatistics& named = recording_->views.emplace_back();
    named.view = view;
    named.pass_kind = pass_kind;
    named.pass_view = pass_view;
    view_open_ = true;
    const auto index = static_cast<std::uint32_t>(recording_->views.size() - 1);
    if (*recording_->statistics) cmd.beginQuery(*recording_->statistics, index, {});
}

void FrameProfiler::end_view(const vk::raii::CommandBuffer& cmd) {
    MONOPLANE_EXPECTS(view_open_);
    view_open_ = false;
    const auto index = static_cast<std::uint32_t>(recording_->views.size() - 1);
    if (*recording_->statistics) cmd.endQuery(*recording_->statistics, index);
}

FrameStats FrameProfiler::collect(std::uint32_t slot_index) const {
    MONOPLANE_EXPECTS(!pass_open_ && !view_open_ && slot_index < slots_.size());
    const Slot& slot = slots_[slot_index];
    FrameStats stats;
    if (!slot.passes.empty()) {
        const auto count = static_cast<std::uint32_t>(2 * slot.passes.size());
        const auto [result, ticks] = slot.timestamps.getResults<std::uint64_t>(
            0, count, count * sizeof(std::uint64_t), sizeof(std::uint64_t),
            vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
        MONOPLANE_EXPECTS(result == vk::Result::eSuccess);
        const std::uint32_t bits = ctx_.capabilities().timestamp_valid_bits;
        const std::uint64_t mask = bits >= 64 ? ~0ull : ((1ull << bits) - 1);
        const double ms_per_tick = ctx_.capabilities().timestamp_period_ns * 1e-6;
        auto elapsed_ms = [&](std::uint64_t begin, std::uint64_t end) {
            return static_cast<double>((end - begin) & mask) * ms_per_tick;
        };
        for (std::size_t i = 0; i < slot.passes.size(); ++i) {
            PassTime& pass = stats.passes.emplace_back(slot.passes[i]);
            pass.gpu_ms = elapsed_ms(ticks[2 * i], ticks[2 * i + 1]);
        }
        stats.gpu_frame_ms = elapsed_ms(ticks.front(), ticks.back());
    }
    if (*slot.statistics && !slot.views.empty()) {
        const std::size_t per_view = counter_fields_.size();
        const auto count = static_cast<std::uint32_t>(slot.views.size());
        const std::size_t stride = per_view * sizeof(std::uint64_t);
        const auto [result, values] = slot.statistics.getResults<std::uint64_t>(
            0, count, count * stride, stride,
            vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
        MONOPLANE_EXPECTS(result == vk::Result::eSuccess);
        for (std::size_t i = 0; i < slot.views.size(); ++i) {
            ViewStatistics view = slot.views[i];
            for (std::size_t k = 0; k < per_view; ++k) {
                view.*counter_fields_[k] = values[i * per_view + k];
            }
            stats.views.push_back(std::move(view));
        }
    }
    return stats;
}

}  // namespace monoplane::profile
