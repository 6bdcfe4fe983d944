#include "renderer/passes/ssao/ssao_pass.h"

#include <array>
#include <cstring>
#include <initializer_list>
#include <span>
#include <string>

#include "common/programming_error.h"
#include "renderer/executor/image_layouts.h"
#include "renderer/passes/forward/forward_pass.h"
#include "renderer/passes/shared/dispatch_groups.h"
#include "renderer/passes/shared/fullscreen_pass.h"

namespace monoplane::passes {
namespace {

// A step's name in the plan: the action alone in C's pass, after the eye's name in the eyes'
// ("left.estimate").
std::string step_name(std::string_view view, std::string_view action) {
    return view.empty() ? std::string(action) : std::string(view) + "." + std::string(action);
}

const std::uint32_t kHbaoEstimate[] = {
#include "hbao_estimate.comp.spv.inc"
};
const std::uint32_t kStereoVisibility[] = {
#include "stereo_visibility.comp.spv.inc"
};
const std::uint32_t kStereoEstimate[] = {
#include "stereo_estimate.comp.spv.inc"
};
const std::uint32_t kBilateralFilter[] = {
#include "bilateral_filter.comp.spv.inc"
};
const std::uint32_t kSsaoApply[] = {
#include "ssao_apply.frag.spv.inc"
};

using Type = vk::DescriptorType;

constexpr std::uint32_t kSsaoGroup = 8;  // the compute shaders' local size in x and y
constexpr vk::Format kOtherPixelFormat = vk::Format::eR32Uint;  // L: p* packed, or "not visible"

// Mirrors ssao_common.glsl's flags.
constexpr std::int32_t kFlagVertical = 1;
constexpr std::int32_t kFlagStereo = 2;
constexpr std::int32_t kFlagReproject = 4;

// The compute shaders' push-constant block (ssao_common.glsl), std430.
struct SsaoPush {
    std::int32_t area_width;
    std::int32_t area_height;
    std::int32_t directions;
    std::int32_t steps;
    float radius;
    float angle_bias;
    float strength;
    float eta;
    float sigma_min;
    float sigma_max;
    float back_check_px;
    std::int32_t taps;
    std::int32_t flags;
    float skip_beyond;
};
static_assert(sizeof(SsaoPush) == 56, "must match ssao_common.glsl");

struct ApplyPush {
    float area_width;
    float area_height;
};
static_assert(sizeof(ApplyPush) == 8, "must match ssao_apply.frag");

// hdr *= AO: the output (AO, AO, AO, 1) blends as dst * src; the target's alpha is kept. The
// depth test (reversed Z, the triangle at 0) passes only where the eye's depth holds near content.
vk::raii::Pipeline make_apply_pipeline(const vk_core::Context& ctx, vk::PipelineLayout layout,
                                       vk::ShaderModule vert, vk::ShaderModule frag,
                                       bool near_only) {
    vk_core::GraphicsPipelineDesc desc;
    desc.layout = layout;
    desc.vertex = vert;
    desc.fragment = frag;
    desc.color_formats = {ForwardPass::kHdrFormat};
    desc.depth_format = near_only ? ForwardPass::kDepthFormat : vk::Format::eUndefined;
    desc.cull = vk::CullModeFlagBits::eNone;
    desc.depth_test = near_only;
    desc.depth_write = false;
    desc.depth_compare = vk::CompareOp::eLess;
    desc.blend =
        vk::PipelineColorBlendAttachmentState()
            .setBlendEnable(VK_TRUE)
            .setSrcColorBlendFactor(vk::BlendFactor::eZero)
            .setDstColorBlendFactor(vk::BlendFactor::eSrcColor)
            .setColorBlendOp(vk::BlendOp::eAdd)
            .setSrcAlphaBlendFactor(vk::BlendFactor::eZero)
            .setDstAlphaBlendFactor(vk::BlendFactor::eOne)
            .setAlphaBlendOp(vk::BlendOp::eAdd)
            .setColorWriteMask(vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
                               vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA);
    return vk_core::make_graphics_pipeline(ctx, desc);
}

}  // namespace

std::optional<SsaoVariant> parse_ssao_variant(const std::string& name) {
    if (name == "per-eye") return SsaoVariant::kPerView;
    if (name == "stereo") return SsaoVariant::kStereoConsistent;
    return std::nullopt;
}

std::string ssao_variant_name(SsaoVariant variant) {
    switch (variant) {
        case SsaoVariant::kPerView:
            return "per-eye";
        case SsaoVariant::kStereoConsistent:
            return "stereo";
    }
    return "?";
}

struct SsaoView::State {
    vk::Extent2D extent;
    // Scratch, always eGeneral: the estimate, the horizontal filter pass, the visibility map L.
    vk_core::Image raw;
    vk_core::Image filtered_x;
    vk_core::Image other_pixel;
    // The result, eShaderReadOnlyOptimal between recordings (eGeneral while written).
    vk_core::Image ao;
    vk_core::Buffer readback;
    vk::raii::DescriptorPool pool{nullptr};
    vk::raii::DescriptorSet compute_set{nullptr};  // ssao_common.glsl's bindings of one view
    vk::raii::DescriptorSet apply_set{nullptr};    // the AO, sampled

    State(const vk_core::Context& ctx, vk::Extent2D size)
        : extent(size),
          raw(ctx, {size, SsaoPass::kAoFormat, vk::ImageUsageFlagBits::eStorage}),
          filtered_x(ctx, {size, SsaoPass::kAoFormat, vk::ImageUsageFlagBits::eStorage}),
          other_pixel(ctx, {size, kOtherPixelFormat, vk::ImageUsageFlagBits::eStorage}),
          ao(ctx,
             {size, SsaoPass::kAoFormat,
              vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eSampled |
                  vk::ImageUsageFlagBits::eTransferSrc | vk::ImageUsageFlagBits::eTransferDst}),
          readback(ctx, vk::DeviceSize{size.width} * size.height * sizeof(float),
                   vk::BufferUsageFlagBits::eTransferDst, vk_core::MemoryUse::kHostVisible) {}
};

SsaoView::SsaoView(std::unique_ptr<State> state) : state_(std::move(state)) {}
SsaoView::~SsaoView() = default;

const vk_core::Image& SsaoView::ao() const {
    return state_->ao;
}

std::vector<const vk_core::Image*> SsaoView::scratch() const {
    return {&state_->raw, &state_->filtered_x, &state_->other_pixel};
}

vk::Extent2D SsaoView::extent() const {
    return state_->extent;
}

const vk_core::Buffer& SsaoView::readback() const {
    return state_->readback;
}

std::vector<float> SsaoView::ao_values() const {
    std::vector<float> values(std::size_t{state_->extent.width} * state_->extent.height);
    std::memcpy(values.data(), state_->readback.mapped(), values.size() * sizeof(float));
    return values;
}

struct SsaoPass::Impl {
    vk::raii::Sampler nearest{nullptr};
    vk::raii::DescriptorSetLayout view_layout{nullptr};
    vk::raii::DescriptorSetLayout apply_layout{nullptr};
    vk::raii::PipelineLayout compute_layout{nullptr};  // set 0: this view, set 1: the other
    vk::raii::PipelineLayout apply_pipeline_layout{nullptr};
    vk::raii::Pipeline hbao_estimate{nullptr};
    vk::raii::Pipeline stereo_visibility{nullptr};
    vk::raii::Pipeline stereo_estimate{nullptr};
    vk::raii::Pipeline bilateral_filter{nullptr};
    vk::raii::Pipeline apply_everywhere{nullptr};
    vk::raii::Pipeline apply_near_only{nullptr};

    SsaoPush push(const SsaoParams& params, vk::Extent2D area, std::int32_t flags,
                  float skip_beyond) const {
        return {static_cast<std::int32_t>(area.width),
                static_cast<std::int32_t>(area.height),
                params.directions,
                params.steps,
                params.radius,
                params.angle_bias,
                params.strength,
                params.eta,
                params.sigma_min,
                params.sigma_max,
                params.back_check_px,
                params.filter_taps,
                flags,
                skip_beyond};
    }

    // One dispatch over the area with `self` as set 0 and `other` as set 1.
    void dispatch(const vk::raii::CommandBuffer& cmd, const vk::raii::Pipeline& pipeline,
                  const SsaoView& self, const SsaoView& other, const SsaoPush& block,
                  vk::Extent2D area) const {
        cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline);
        const std::array sets = {*self.state_->compute_set, *other.state_->compute_set};
        cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *compute_layout, 0, sets, {});
        cmd.pushConstants<SsaoPush>(*compute_layout, vk::ShaderStageFlagBits::eCompute, 0, block);
        cmd.dispatch(groups_covering(area.width, kSsaoGroup),
                     groups_covering(area.height, kSsaoGroup), 1);
    }
};

SsaoPass::SsaoPass(const vk_core::Context& ctx, const SsaoParams& params)
    : ctx_(ctx), params_(params), impl_(std::make_unique<Impl>()) {
    MONOPLANE_EXPECTS(params.directions > 0 && params.steps > 0 && params.filter_taps > 0);
    MONOPLANE_EXPECTS(params.radius > 0.0f && params.sigma_min > 0.0f &&
                      params.sigma_min <= params.sigma_max);
    Impl& impl = *impl_;
    impl.nearest = vk_core::make_clamped_sampler(ctx, vk::Filter::eNearest);
    const auto compute = vk::ShaderStageFlagBits::eCompute;
    const std::array view_bindings = {
        vk::DescriptorSetLayoutBinding(0, Type::eUniformBuffer, 1, compute),
        vk::DescriptorSetLayoutBinding(1, Type::eCombinedImageSampler, 1, compute),
        vk::DescriptorSetLayoutBinding(2, Type::eStorageImage, 1, compute),
        vk::DescriptorSetLayoutBinding(3, Type::eStorageImage, 1, compute),
        vk::DescriptorSetLayoutBinding(4, Type::eStorageImage, 1, compute),
        vk::DescriptorSetLayoutBinding(5, Type::eStorageImage, 1, compute),
    };
    impl.view_layout = vk::raii::DescriptorSetLayout(
        ctx.device(), vk::DescriptorSetLayoutCreateInfo({}, view_bindings));
    const vk::DescriptorSetLayoutBinding apply_binding(0, Type::eCombinedImageSampler, 1,
                                                       vk::ShaderStageFlagBits::eFragment);
    impl.apply_layout = vk::raii::DescriptorSetLayout(
        ctx.device(), vk::DescriptorSetLayoutCreateInfo({}, apply_binding));

    const std::array compute_sets = {*impl.view_layout, *impl.view_layout};
    const vk::PushConstantRange compute_push(compute, 0, sizeof(SsaoPush));
    impl.compute_layout = vk::raii::PipelineLayout(
        ctx.device(), vk::PipelineLayoutCreateInfo({}, compute_sets, compute_push));
    const vk::DescriptorSetLayout apply_set = *impl.apply_layout;
    const vk::PushConstantRange apply_push(vk::ShaderStageFlagBits::eFragment, 0,
                                           sizeof(ApplyPush));
    impl.apply_pipeline_layout = vk::raii::PipelineLayout(
        ctx.device(), vk::PipelineLayoutCreateInfo({}, apply_set, apply_push));

    const auto make = [&](std::span<const std::uint32_t> spirv) {
        const vk::raii::ShaderModule module = vk_core::make_shader(ctx, spirv);
        return vk_core::make_compute_pipeline(ctx, *impl.compute_layout, *module);
    };
    impl.hbao_estimate = make(kHbaoEstimate);
    impl.stereo_visibility = make(kStereoVisibility);
    impl.stereo_estimate = make(kStereoEstimate);
    impl.bilateral_filter = make(kBilateralFilter);

    const vk::raii::ShaderModule vert = make_fullscreen_vertex_shader(ctx);
    const vk::raii::ShaderModule frag = vk_core::make_shader(ctx, kSsaoApply);
    impl.apply_everywhere =
        make_apply_pipeline(ctx, *impl.apply_pipeline_layout, *vert, *frag, false);
    impl.apply_near_only =
        make_apply_pipeline(ctx, *impl.apply_pipeline_layout, *vert, *frag, true);
}

SsaoPass::~SsaoPass() = default;

std::unique_ptr<SsaoView> SsaoPass::make_view(const vk_core::Buffer& constants,
                                              const vk_core::Image& linear_depth,
                                              vk::Extent2D extent) const {
    MONOPLANE_EXPECTS(linear_depth.desc().extent == extent);
    MONOPLANE_EXPECTS(constants.size() >= sizeof(ViewConstants));
    auto state = std::make_unique<SsaoView::State>(ctx_, extent);

    const std::array pool_sizes = {vk::DescriptorPoolSize(Type::eUniformBuffer, 1),
                                   vk::DescriptorPoolSize(Type::eCombinedImageSampler, 2),
                                   vk::DescriptorPoolSize(Type::eStorageImage, 4)};
    state->pool = vk::raii::DescriptorPool(
        ctx_.device(), vk::DescriptorPoolCreateInfo(
                           vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 2, pool_sizes));
    const std::array layouts = {*impl_->view_layout, *impl_->apply_layout};
    vk::raii::DescriptorSets sets(ctx_.device(),
                                  vk::DescriptorSetAllocateInfo(*state->pool, layouts));
    state->compute_set = std::move(sets[0]);
    state->apply_set = std::move(sets[1]);

    const vk::DescriptorBufferInfo constants_info(constants.handle(), 0, sizeof(ViewConstants));
    const vk::DescriptorImageInfo depth_info(*impl_->nearest, linear_depth.view(),
                                             executor::layout_for(graph::Use::kSampledCompute));
    const auto storage = [](const vk_core::Image& image) {
        return vk::DescriptorImageInfo(nullptr, image.view(),
                                       executor::layout_for(graph::Use::kStorageWrite));
    };
    const vk::DescriptorImageInfo other_pixel_info = storage(state->other_pixel);
    const vk::DescriptorImageInfo raw_info = storage(state->raw);
    const vk::DescriptorImageInfo filtered_info = storage(state->filtered_x);
    const vk::DescriptorImageInfo ao_info = storage(state->ao);
    const vk::DescriptorImageInfo ao_sampled(*impl_->nearest, state->ao.view(),
                                             executor::layout_for(graph::Use::kSampledFragment));
    const vk::DescriptorSet set = *state->compute_set;
    const std::array writes = {
        vk::WriteDescriptorSet(set, 0, 0, Type::eUniformBuffer, {}, constants_info),
        vk::WriteDescriptorSet(set, 1, 0, Type::eCombinedImageSampler, depth_info),
        vk::WriteDescriptorSet(set, 2, 0, Type::eStorageImage, other_pixel_info),
        vk::WriteDescriptorSet(set, 3, 0, Type::eStorageImage, raw_info),
        vk::WriteDescriptorSet(set, 4, 0, Type::eStorageImage, filtered_info),
        vk::WriteDescriptorSet(set, 5, 0, Type::eStorageImage, ao_info),
        vk::WriteDescriptorSet(*state->apply_set, 0, 0, Type::eCombinedImageSampler, ao_sampled),
    };
    ctx_.device().updateDescriptorSets(writes, {});

    // Scratch images live in eGeneral; the AO starts as 1 everywhere (outside the area it stays
    // so), shader-readable as if a frame had computed it.
    for (vk_core::Image* image : {&state->raw, &state->filtered_x, &state->other_pixel}) {
        vk_core::initialise_image(ctx_, *image, executor::layout_for(graph::Use::kStorageWrite));
    }
    vk_core::initialise_image(ctx_, state->ao, executor::layout_for(graph::Use::kSampledFragment),
                              vk::ClearColorValue(std::array{1.0f, 1.0f, 1.0f, 1.0f}));
    return std::unique_ptr<SsaoView>(new SsaoView(std::move(state)));
}

void SsaoPass::record_view(const vk::raii::CommandBuffer& cmd, StepSync& sync, SsaoView& view,
                           vk::Extent2D area, float skip_beyond, std::string_view step_view) const {
    MONOPLANE_EXPECTS(area.width <= view.extent().width && area.height <= view.extent().height);
    const Impl& impl = *impl_;
    const SsaoPush plain = impl.push(params_, area, 0, skip_beyond);
    sync.next(cmd, step_name(step_view, "estimate"));
    impl.dispatch(cmd, impl.hbao_estimate, view, view, plain, area);
    sync.next(cmd, step_name(step_view, "filter-x"));
    impl.dispatch(cmd, impl.bilateral_filter, view, view, plain, area);
    sync.next(cmd, step_name(step_view, "filter-y"));
    impl.dispatch(cmd, impl.bilateral_filter, view, view,
                  impl.push(params_, area, kFlagVertical, skip_beyond), area);
}

float SsaoPass::skip_margin() const {
    // The filter weighs a tap by G_sigma of its world distance, sigma <= sigma_max: at 6 sigma
    // the weight is exp(-18) of the centre's, below any 8-bit level.
    return 6.0f * params_.sigma_max;
}

void SsaoPass::record_pair(const vk::raii::CommandBuffer& cmd, StepSync& sync, SsaoView& left,
                           SsaoView& right, vk::Extent2D area, SsaoVariant variant,
                           float skip_beyond) const {
    MONOPLANE_EXPECTS(left.extent() == right.extent());
    if (variant == SsaoVariant::kPerView) {
        record_view(cmd, sync, left, area, skip_beyond, "left");
        record_view(cmd, sync, right, area, skip_beyond, "right");
        return;
    }
    MONOPLANE_EXPECTS(area.width <= left.extent().width && area.height <= left.extent().height);
    const Impl& impl = *impl_;
    // Sect. 3.1: the visibility maps L^l and L^r by reverse reprojection with a back-check.
    const SsaoPush plain = impl.push(params_, area, 0, skip_beyond);
    sync.next(cmd, "visibility-left");
    impl.dispatch(cmd, impl.stereo_visibility, left, right, plain, area);
    sync.next(cmd, "visibility-right");
    impl.dispatch(cmd, impl.stereo_visibility, right, left, plain, area);
    // Sect. 3.1: the left eye's stereo estimate; Sect. 3.2: the right eye reprojects it where
    // L^r allows and estimates the rest from scratch.
    sync.next(cmd, "estimate-left");
    impl.dispatch(cmd, impl.stereo_estimate, left, right, plain, area);
    sync.next(cmd, "estimate-right");
    impl.dispatch(cmd, impl.stereo_estimate, right, left,
                  impl.push(params_, area, kFlagReproject, skip_beyond), area);
    // Sect. 3.3: the stereo filter, horizontally in both views, then vertically on that.
    const SsaoPush horizontal = impl.push(params_, area, kFlagStereo, skip_beyond);
    sync.next(cmd, "filter-x-left");
    impl.dispatch(cmd, impl.bilateral_filter, left, right, horizontal, area);
    sync.next(cmd, "filter-x-right");
    impl.dispatch(cmd, impl.bilateral_filter, right, left, horizontal, area);
    const SsaoPush vertical = impl.push(params_, area, kFlagStereo | kFlagVertical, skip_beyond);
    sync.next(cmd, "filter-y-left");
    impl.dispatch(cmd, impl.bilateral_filter, left, right, vertical, area);
    sync.next(cmd, "filter-y-right");
    impl.dispatch(cmd, impl.bilateral_filter, right, left, vertical, area);
}

void SsaoPass::record_apply(const vk::raii::CommandBuffer& cmd, StepSync& sync,
                            const SsaoView& view, const vk_core::Image& hdr, vk::Extent2D area,
                            const vk_core::Image* near_only_depth,
                            std::string_view step_view) const {
    MONOPLANE_EXPECTS(hdr.desc().format == ForwardPass::kHdrFormat);
    MONOPLANE_EXPECTS(!near_only_depth ||
                      near_only_depth->desc().format == ForwardPass::kDepthFormat);
    const Impl& impl = *impl_;
    sync.next(cmd, step_name(step_view, "apply"));
    const vk::RenderingAttachmentInfo color(
        hdr.view(), executor::layout_for(graph::Use::kColorBlend), {}, {}, {},
        vk::AttachmentLoadOp::eLoad, vk::AttachmentStoreOp::eStore);
    auto rendering = vk::RenderingInfo()
                         .setRenderArea(vk::Rect2D({0, 0}, area))
                         .setLayerCount(1)
                         .setColorAttachments(color);
    vk::RenderingAttachmentInfo depth;
    if (near_only_depth) {
        depth = vk::RenderingAttachmentInfo(
            near_only_depth->view(), executor::layout_for(graph::Use::kDepthTest), {}, {}, {},
            vk::AttachmentLoadOp::eLoad, vk::AttachmentStoreOp::eStore);
        rendering.setPDepthAttachment(&depth);
    }
    cmd.beginRendering(rendering);
    vk_core::set_viewport_and_scissor(cmd, area);
    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics,
                     near_only_depth ? *impl.apply_near_only : *impl.apply_everywhere);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *impl.apply_pipeline_layout, 0,
                           *view.state_->apply_set, {});
    const ApplyPush push{static_cast<float>(area.width), static_cast<float>(area.height)};
    cmd.pushConstants<ApplyPush>(*impl.apply_pipeline_layout, vk::ShaderStageFlagBits::eFragment, 0,
                                 push);
    cmd.draw(3, 1, 0, 0);
    cmd.endRendering();
}

void SsaoPass::record_readback(const vk::raii::CommandBuffer& cmd, SsaoView& view) const {
    SsaoView::State& state = *view.state_;
    cmd.copyImageToBuffer(
        state.ao.handle(), executor::layout_for(graph::Use::kTransferSrc), state.readback.handle(),
        vk::BufferImageCopy(0, 0, 0,
                            vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, 0, 1),
                            {0, 0, 0}, vk::Extent3D(state.extent, 1)));
}

}  // namespace monoplane::passes
