#include "renderer/executor/graph_executor.h"

#include <algorithm>
#include <string>
#include <string_view>

#include "common/programming_error.h"
#include "renderer/executor/image_layouts.h"

namespace monoplane::executor {
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

namespace {

// A pass records the step its plan declares next, or the two disagree: a programming error.
void expect_declared(const plan::PlannedPass& pass, const std::string& declared,
                     std::string_view recorded) {
    if (recorded == declared) return;
    programming_error(pass.name + " recorded step '" + std::string(recorded) +
                      "' where its plan declares '" + declared + "'");
}

}  // namespace

// The steps of the pass being recorded, in the plan's order.
class GraphExecutor::PassSync : public passes::StepSync {
  public:
    PassSync(GraphExecutor& executor, std::size_t pass) : executor_(executor), pass_(pass) {}

    void next(const vk::raii::CommandBuffer& cmd, std::string_view step) override {
        const auto& steps = executor_.compiled_.steps[pass_];
        const plan::PlannedPass& pass = executor_.plan_->passes[pass_];
        const auto& declared = pass.steps;
        if (next_ < steps.size()) {
            expect_declared(pass, declared[next_].name, step);
            executor_.record(cmd, steps[next_].before);
            ++next_;
            return;
        }
        if (next_ == 0 || !declared[next_ - 1].repeats) {
            programming_error(pass.name + " recorded step '" + std::string(step) +
                              "' after the last step its plan declares");
        }
        expect_declared(pass, declared[next_ - 1].name, step);
        executor_.record(cmd, steps[next_ - 1].between_repeats);
    }

    // Whether every declared step was begun (a repeating last step may have run zero times).
    bool complete() const {
        const auto& declared = executor_.plan_->passes[pass_].steps;
        if (next_ >= declared.size()) return true;
        return next_ + 1 == declared.size() && declared.back().repeats;
    }

    std::size_t pass() const { return pass_; }

  private:
    GraphExecutor& executor_;
    std::size_t pass_;
    std::size_t next_ = 0;
};

GraphExecutor::GraphExecutor() = default;
GraphExecutor::~GraphExecutor() = default;

void GraphExecutor::begin_frame(const plan::FramePlan& plan, std::vector<BoundResource> bindings) {
    MONOPLANE_EXPECTS(bindings.size() == plan.resources.size());
    plan_ = &plan;
    bindings_ = std::move(bindings);
    // Consecutive frames of one plan start from the same states (TAA's two history images swap
    // roles and states together): compile only when either changed.
    std::vector<graph::ResourceState> initial = initial_states();
    graph::Aliasing aliasing = this->aliasing();
    if (plan_generation_ != compiled_generation_ || initial != compiled_initial_ ||
        aliasing != compiled_aliasing_) {
        compiled_ =
            graph::compile(plan.resources, plan.graph_passes(), plan.exports, initial, aliasing);
        compiled_initial_ = std::move(initial);
        compiled_aliasing_ = std::move(aliasing);
        compiled_generation_ = plan_generation_;
    }
    keep_final_states(compiled_.final_states);
}

passes::StepSync& GraphExecutor::begin_pass(const vk::raii::CommandBuffer& cmd, std::size_t pass) {
    sync_ = std::make_unique<PassSync>(*this, pass);
    // A pass of one step is begun here: the pass records that step and nothing else.
    const std::vector<graph::Step>& steps = plan_->passes[pass].steps;
    if (steps.size() == 1) sync_->next(cmd, steps.front().name);
    return *sync_;
}

void GraphExecutor::end_pass() {
    // A pass and its plan disagree: a programming error the GPU tests must see in any build.
    MONOPLANE_EXPECTS(sync_ != nullptr);
    if (!sync_->complete()) {
        programming_error(plan_->passes[sync_->pass()].name +
                          " recorded fewer steps than its plan declares");
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
    const ImageId id{image.handle, image.base_layer};
    image_states_.erase(id);
    std::erase_if(memory_holders_, [&](const auto& holder) { return holder.second == id; });
}

void GraphExecutor::record(const vk::raii::CommandBuffer& cmd,
                           const std::vector<graph::Barrier>& barriers) {
    std::vector<vk::MemoryBarrier2> memory;
    std::vector<vk::ImageMemoryBarrier2> images;
    for (graph::Barrier b : barriers) {
        if (drop_ && drop_(b, *plan_)) {
            if (b.old_layout == b.new_layout) continue;
            b.src_stages = Stage::kNone;
            b.src_access = Access::kNone;
        }
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

graph::Aliasing GraphExecutor::aliasing() {
    graph::Aliasing aliasing;
    memories_.clear();
    for (const BoundResource& bound : bindings_) {
        const vk::DeviceMemory memory =
            bound.images.empty() ? vk::DeviceMemory{} : bound.images.front().shared_memory;
        std::int32_t index = -1;
        if (memory) {
            const auto it = std::find(memories_.begin(), memories_.end(), memory);
            index = static_cast<std::int32_t>(it - memories_.begin());
            if (it == memories_.end()) memories_.push_back(memory);
        }
        aliasing.memory.push_back(index);
    }
    if (memories_.empty()) return {};
    for (const vk::DeviceMemory memory : memories_) {
        graph::MemoryHolder& holder = aliasing.initial.emplace_back();
        const auto last = memory_holders_.find(memory);
        if (last == memory_holders_.end()) continue;  // no frame has used it
        for (std::size_t r = 0; r < bindings_.size(); ++r) {
            const std::vector<vk_core::ImageRange>& images = bindings_[r].images;
            if (!images.empty() &&
                ImageId{images.front().handle, images.front().base_layer} == last->second) {
                holder.resource = static_cast<std::int32_t>(r);
            }
        }
        // An image this plan does not bind: its accesses, as it left them.
        const auto state = image_states_.find(last->second);
        if (holder.resource < 0 && state != image_states_.end()) holder.state = state->second;
    }
    return aliasing;
}

void GraphExecutor::keep_final_states(const std::vector<graph::ResourceState>& states) {
    for (std::size_t m = 0; m < memories_.size(); ++m) {
        const std::int32_t r = compiled_.final_holders.at(m);
        if (r < 0) continue;
        const vk_core::ImageRange& image = bindings_[static_cast<std::size_t>(r)].images.front();
        memory_holders_[memories_[m]] = {image.handle, image.base_layer};
    }
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

}  // namespace monoplane::executor
