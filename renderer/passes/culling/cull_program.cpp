#include "renderer/passes/culling/cull_program.h"

#include <array>
#include <map>

#include "renderer/executor/image_layouts.h"
#include "renderer/vk/pipeline.h"

namespace monoplane::passes {
namespace {

const std::uint32_t kCullChunks[] = {
#include "cull_chunks.comp.spv.inc"
};

using Type = vk::DescriptorType;

constexpr std::array kPoolSizes = {vk::DescriptorPoolSize(Type::eStorageBuffer, 8),
                                   vk::DescriptorPoolSize(Type::eCombinedImageSampler, 1)};

}  // namespace

CullProgram::CullProgram(const vk_core::Context& ctx, Phase phase) : ctx_(ctx) {
    const auto compute = vk::ShaderStageFlagBits::eCompute;
    const std::array bindings = {
        vk::DescriptorSetLayoutBinding(0, Type::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(1, Type::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(2, Type::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(3, Type::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(4, Type::eCombinedImageSampler, 1, compute),
        vk::DescriptorSetLayoutBinding(5, Type::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(6, Type::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(7, Type::eStorageBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(8, Type::eStorageBuffer, 1, compute),
    };
    set_layout_ = vk::raii::DescriptorSetLayout(ctx.device(),
                                                vk::DescriptorSetLayoutCreateInfo({}, bindings));
    const vk::DescriptorSetLayout set_layout = *set_layout_;
    const vk::PushConstantRange push(compute, 0, sizeof(std::uint32_t));
    layout_ =
        vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo({}, set_layout, push));
    const vk::raii::ShaderModule shader = vk_core::make_shader(ctx, kCullChunks);
    pipeline_ = vk_core::make_compute_pipeline(ctx, *layout_, *shader);
    nearest_ = vk_core::make_texel_sampler(ctx);
    if (phase == Phase::kOcclusion) return;
    // Never read: in the layout the pyramid is read in, as a set that names it requires.
    no_pyramid_.emplace(
        ctx, vk_core::ImageDesc{{1, 1}, vk::Format::eR32Sfloat, vk::ImageUsageFlagBits::eSampled});
    vk_core::initialise_image(ctx, *no_pyramid_, executor::layout_for(graph::Use::kGeneralSampled));
}

vk_core::DescriptorSet CullProgram::make_set() const {
    return vk_core::DescriptorSet(ctx_, *set_layout_, kPoolSizes);
}

void CullProgram::bind(vk::DescriptorSet set, const CullBuffers& buffers,
                       const vk_core::Image* merged_depth) const {
    const auto whole = [](const vk_core::Buffer* buffer) {
        return vk::DescriptorBufferInfo(buffer->handle(), 0, VK_WHOLE_SIZE);
    };
    const CullInputs& in = buffers.inputs;
    const std::array infos = {whole(in.chunks),    whole(buffers.commands), whole(buffers.counts),
                              whole(in.constants), whole(in.routing),       whole(in.order),
                              whole(in.levels),    whole(buffers.lod_state)};
    // cull_chunks.comp's bindings 0-3 and 5-8; 4 is the pyramid.
    constexpr std::array<std::uint32_t, 8> kBindings = {0, 1, 2, 3, 5, 6, 7, 8};
    std::array<vk::WriteDescriptorSet, 9> writes;
    for (std::size_t i = 0; i < infos.size(); ++i) {
        writes[i] =
            vk::WriteDescriptorSet(set, kBindings[i], 0, Type::eStorageBuffer, {}, infos[i]);
    }
    const vk::DescriptorImageInfo pyramid(
        *nearest_, merged_depth != nullptr ? merged_depth->view() : no_pyramid_->view(),
        executor::layout_for(graph::Use::kGeneralSampled));
    writes[8] = vk::WriteDescriptorSet(set, 4, 0, Type::eCombinedImageSampler, pyramid);
    ctx_.device().updateDescriptorSets(writes, {});
}

void CullProgram::dispatch(const vk::raii::CommandBuffer& cmd, vk::DescriptorSet set,
                           Phase phase) const {
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline_);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *layout_, 0, set, {});
    cmd.pushConstants<std::uint32_t>(*layout_, vk::ShaderStageFlagBits::eCompute, 0,
                                     static_cast<std::uint32_t>(phase));
    cmd.dispatch(1, 1, 1);
}

namespace {

class CullRecorder final : public UnitRecorder {
  public:
    CullRecorder(const vk_core::Context& ctx, CullProgram::Phase phase)
        : program_(ctx, phase), phase_(phase) {}

    void record(UnitRecording& r) override {
        auto [entry, added] = sets_.try_emplace(r.values().slot);
        if (added) entry->second = program_.make_set();
        CullBuffers buffers;
        buffers.inputs = r.cull_inputs();
        buffers.commands = &r.buffer(plan::ViewId::kNone, plan::BufferRole::kDrawLists);
        buffers.counts = &r.buffer(plan::ViewId::kNone, plan::BufferRole::kPredicates);
        buffers.lod_state = &r.buffer(plan::ViewId::kNone, plan::BufferRole::kLodState);
        // The slot's last frame has completed: its set is free to rewrite (the pyramid may have
        // grown since).
        const vk_core::Image* pyramid =
            phase_ == CullProgram::Phase::kOcclusion
                ? &r.image(plan::ViewId::kNone, plan::ImageRole::kMergedDepth)
                : nullptr;
        program_.bind(*entry->second, buffers, pyramid);
        with_predicate(r.cmd(), r.predicate(r.pass().when),
                       [&] { program_.dispatch(r.cmd(), *entry->second, phase_); });
    }

  private:
    CullProgram program_;
    CullProgram::Phase phase_;
    std::map<std::uint32_t, vk_core::DescriptorSet> sets_;  // per frame slot
};

}  // namespace

std::unique_ptr<UnitRecorder> make_cull_recorder(const vk_core::Context& ctx,
                                                 CullProgram::Phase phase) {
    return std::make_unique<CullRecorder>(ctx, phase);
}

}  // namespace monoplane::passes
