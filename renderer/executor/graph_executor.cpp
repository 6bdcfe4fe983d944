#include "renderer/executor/graph_executor.h"

#include <cassert>
#include <stdexcept>

namespace monoplane::modes {
namespace {

using graph::Access;
using graph::Layout;
using graph::Stage;

vk::PipelineStageFlags2 vk_stages(Stage stages) {
    using S = vk::PipelineStageFlagBits2;
    constexpr std::pair<Stage, S> kTable[] = {
        {Stage::kDrawIndirect, S::eDrawIndirect},
        {Stage::kVertexShader, S::eVertexShader},
        {Stage::kGeometryShader, S::eGeometryShader},
        {Stage::kEarlyFragmentTests, S::eEarlyFragmentTests},
        {Stage::kFragmentShader, S::eFragmentShader},
        {Stage::kLateFragmentTests, S::eLateFragmentTests},
        {Stage::kColorAttachmentOutput, S::eColorAttachmentOutput},
        {Stage::kComputeShader, S::eComputeShader},
        {Stage::kTransfer, S::eAllTransfer},
        {Stage::kConditionalRendering, S::eConditionalRenderingEXT},
        {Stage::kHost, S::eHost},
    };
    vk::PipelineStageFlags2 flags;
    for (const auto& [bit, flag] : kTable) {
        if (graph::covers(stages, bit)) flags |= flag;
    }
    return flags;
}

vk::AccessFlags2 vk_access(Access access) {
    using A = vk::AccessFlagBits2;
    constexpr std::pair<Access, A> kTable[] = {
        {Access::kIndirectCommandRead, A::eIndirectCommandRead},
        {Access::kUniformRead, A::eUniformRead},
        {Access::kShaderSampledRead, A::eShaderSampledRead},
        {Access::kShaderStorageRead, A::eShaderStorageRead},
        {Access::kShaderStorageWrite, A::eShaderStorageWrite},
        {Access::kColorAttachmentRead, A::eColorAttachmentRead},
        {Access::kColorAttachmentWrite, A::eColorAttachmentWrite},
        {Access::kDepthStencilAttachmentRead, A::eDepthStencilAttachmentRead},
        {Access::kDepthStencilAttachmentWrite, A::eDepthStencilAttachmentWrite},
        {Access::kTransferRead, A::eTransferRead},
        {Access::kTransferWrite, A::eTransferWrite},
        {Access::kHostRead, A::eHostRead},
        {Access::kConditionalRenderingRead, A::eConditionalRenderingReadEXT},
    };
    vk::AccessFlags2 flags;
    for (const auto& [bit, flag] : kTable) {
        if (graph::covers(access, bit)) flags |= flag;
    }
    return flags;
}

vk::ImageLayout vk_layout(Layout layout) {
    switch (layout) {
        case Layout::kUndefined:
            return vk::ImageLayout::eUndefined;
        case Layout::kGeneral:
            return vk::ImageLayout::eGeneral;
        case Layout::kColorAttachment:
            return vk::ImageLayout::eColorAttachmentOptimal;
        case Layout::kDepthAttachment:
            return vk::ImageLayout::eDepthAttachmentOptimal;
        case Layout::kDepthReadOnly:
            return vk::ImageLayout::eDepthReadOnlyOptimal;
        case Layout::kShaderReadOnly:
            return vk::ImageLayout::eShaderReadOnlyOptimal;
        case Layout::kTransferSrc:
            return vk::ImageLayout::eTransferSrcOptimal;
        case Layout::kTransferDst:
            return vk::ImageLayout::eTransferDstOptimal;
    }
    return vk::ImageLayout::eUndefined;
}

// The graph's name for a layout an image was made in.
Layout graph_layout(vk::ImageLayout layout) {
    for (Layout l : {Layout::kGeneral, Layout::kColorAttachment, Layout::kDepthAttachment,
                     Layout::kDepthReadOnly, Layout::kShaderReadOnly, Layout::kTransferSrc,
                     Layout::kTransferDst}) {
        if (vk_layout(l) == layout) return l;
    }
    return Layout::kUndefined;
}

// A barrier with nothing before it to wait for (a first use) still needs a source stage.
vk::PipelineStageFlags2 source_stages(const graph::Barrier& b) {
    const vk::PipelineStageFlags2 stages = vk_stages(b.src_stages);
    return stages ? stages : vk::PipelineStageFlags2(vk::PipelineStageFlagBits2::eNone);
}

}  // namespace

// The steps of the pass being recorded, in the plan's order.
class GraphExecutor::PassSync : public passes::StepSync {
  public:
    PassSync(GraphExecutor& executor, std::size_t pass) : executor_(executor), pass_(pass) {}

    void next(const vk::raii::CommandBuffer& cmd) override {
        const auto& steps = executor_.compiled_.steps[pass_];
        const auto& declared = executor_.plan_->passes[pass_].steps;
        if (next_ < steps.size()) {
            executor_.record(cmd, steps[next_].before);
            ++next_;
            return;
        }
        if (next_ == 0 || !declared[next_ - 1].repeats) {
            throw std::logic_error(executor_.plan_->passes[pass_].name +
                                   " recorded more steps than its plan declares");
        }
        executor_.record(cmd, steps[next_ - 1].between_repeats);
    }

    // Whether every declared step was begun (a repeating last step may have run zero times).
    bool complete() const {
        const auto& declared = executor_.plan_->passes[pass_].steps;
        if (next_ >= declared.size()) return true;
        return next_ + 1 == declared.size() && declared.back().repeats;
    }

  private:
    GraphExecutor& executor_;
    std::size_t pass_;
    std::size_t next_ = 0;
};

GraphExecutor::GraphExecutor() = default;
GraphExecutor::~GraphExecutor() = default;

void GraphExecutor::begin_frame(const FramePlan& plan, std::vector<BoundResource> bindings) {
    assert(bindings.size() == plan.resources.size());
    plan_ = &plan;
    bindings_ = std::move(bindings);
    // Consecutive frames of one plan start from the same states (TAA's two history images swap
    // roles and states together): compile only when either changed.
    std::vector<graph::ResourceState> initial = initial_states();
    if (plan_generation_ != compiled_generation_ || initial != compiled_initial_) {
        compiled_ = graph::compile(plan.resources, plan.graph_passes(), plan.exports, initial);
        compiled_initial_ = std::move(initial);
        compiled_generation_ = plan_generation_;
    }
    keep_final_states(compiled_.final_states);
}

passes::StepSync& GraphExecutor::begin_pass(const vk::raii::CommandBuffer& cmd, std::size_t pass) {
    sync_ = std::make_unique<PassSync>(*this, pass);
    if (plan_->passes[pass].steps.size() == 1) sync_->next(cmd);
    return *sync_;
}

void GraphExecutor::end_pass() {
    // A pass and its plan disagree: a programming error the GPU tests must see in any build.
    if (!sync_ || !sync_->complete()) {
        throw std::logic_error("a pass recorded fewer steps than its plan declares");
    }
    sync_.reset();
}

void GraphExecutor::end_frame(const vk::raii::CommandBuffer& cmd) {
    record(cmd, compiled_.final_barriers);
}

vk::ImageLayout GraphExecutor::layout_of(const vk_core::ImageRange& image) const {
    const auto it = image_states_.find({image.handle, image.base_layer});
    return it == image_states_.end() ? image.initial_layout : vk_layout(it->second.layout);
}

void GraphExecutor::forget(const vk_core::ImageRange& image) {
    image_states_.erase({image.handle, image.base_layer});
}

void GraphExecutor::record(const vk::raii::CommandBuffer& cmd,
                           const std::vector<graph::Barrier>& barriers) {
    std::vector<vk::MemoryBarrier2> memory;
    std::vector<vk::ImageMemoryBarrier2> images;
    for (const graph::Barrier& b : barriers) {
        if (drop_ && drop_(b, *plan_)) continue;
        const vk::PipelineStageFlags2 src = source_stages(b);
        const vk::PipelineStageFlags2 dst = vk_stages(b.dst_stages);
        if (plan_->resources[b.resource].kind == graph::ResourceKind::kBuffer) {
            memory.emplace_back(src, vk_access(b.src_access), dst, vk_access(b.dst_access));
            continue;
        }
        for (const vk_core::ImageRange& image : bindings_[b.resource].images) {
            images.emplace_back(src, vk_access(b.src_access), dst, vk_access(b.dst_access),
                                vk_layout(b.old_layout), vk_layout(b.new_layout),
                                VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, image.handle,
                                vk::ImageSubresourceRange(image.aspect, 0, image.mip_levels,
                                                          image.base_layer, image.layers));
        }
    }
    if (memory.empty() && images.empty()) return;
    cmd.pipelineBarrier2(vk::DependencyInfo({}, memory, {}, images));
}

std::vector<graph::ResourceState> GraphExecutor::initial_states() const {
    std::vector<graph::ResourceState> states(plan_->resources.size());
    for (std::size_t r = 0; r < states.size(); ++r) {
        const graph::ResourceDesc& desc = plan_->resources[static_cast<std::uint16_t>(r)];
        if (desc.kind == graph::ResourceKind::kBuffer) {
            const auto it = buffer_states_.find(desc.name);
            if (it != buffer_states_.end()) states[r] = it->second;
            continue;
        }
        if (bindings_[r].shared_state != nullptr) {
            states[r] = *bindings_[r].shared_state;
            continue;
        }
        // Images bound together (SSAO's scratch images) are always used together. An image no
        // frame has used yet is in the layout it was made in.
        const std::vector<vk_core::ImageRange>& images = bindings_[r].images;
        if (images.empty()) continue;  // used only by passes the frame leaves out
        const auto it = image_states_.find({images.front().handle, images.front().base_layer});
        if (it != image_states_.end()) {
            states[r] = it->second;
        } else {
            states[r].layout = graph_layout(images.front().initial_layout);
        }
    }
    return states;
}

void GraphExecutor::keep_final_states(const std::vector<graph::ResourceState>& states) {
    for (std::size_t r = 0; r < states.size(); ++r) {
        const graph::ResourceDesc& desc = plan_->resources[static_cast<std::uint16_t>(r)];
        if (desc.kind == graph::ResourceKind::kBuffer) {
            buffer_states_[desc.name] = states[r];
            continue;
        }
        if (bindings_[r].shared_state != nullptr) {
            *bindings_[r].shared_state = states[r];
            continue;
        }
        for (const vk_core::ImageRange& image : bindings_[r].images) {
            image_states_[{image.handle, image.base_layer}] = states[r];
        }
    }
}

}  // namespace monoplane::modes
