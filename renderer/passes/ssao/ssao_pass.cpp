#include "renderer/passes/ssao/ssao_pass.h"

#include <array>
#include <cstring>
#include <initializer_list>
#include <span>
#include <string>
#include <utility>

#include "common/programming_error.h"
#include "renderer/executor/image_layouts.h"
#include "renderer/passes/forward/forward_pass.h"
#include "renderer/passes/shared/dispatch_groups.h"
#include "renderer/passes/shared/fullscreen_pass.h"

namespace monoplane::passes {
namespace {

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

SsaoImages::SsaoImages(const vk_core::Context& ctx, vk::Extent2D extent)
    : raw_(ctx, {extent, kAoFormat, vk::ImageUsageFlagBits::eStorage}),
      filtered_x_(ctx, {extent, kAoFormat, vk::ImageUsageFlagBits::eStorage}),
      other_pixel_(ctx, {extent, kOtherPixelFormat, vk::ImageUsageFlagBits::eStorage}),
      ao_(ctx, {extent, kAoFormat,
                vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eSampled |
                    vk::ImageUsageFlagBits::eTransferSrc | vk::ImageUsageFlagBits::eTransferDst}),
      readback_(ctx, vk::DeviceSize{extent.width} * extent.height * sizeof(float),
                vk::BufferUsageFlagBits::eTransferDst, vk_core::MemoryUse::kHostVisible) {
    for (vk_core::Image* image : {&raw_, &filtered_x_, &other_pixel_}) {
        vk_core::initialise_image(ctx, *image, executor::layout_for(graph::Use::kStorageWrite));
    }
    vk_core::initialise_image(ctx, ao_, executor::layout_for(graph::Use::kSampledFragment),
                              vk::ClearColorValue(std::array{1.0f, 1.0f, 1.0f, 1.0f}));
}

std::vector<float> SsaoImages::ao_values() const {
    std::vector<float> values(std::size_t{extent().width} * extent().height);
    std::memcpy(values.data(), readback_.mapped(), values.size() * sizeof(float));
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

    static SsaoPush push(const SsaoParams& params, vk::Extent2D area, std::int32_t flags,
                         float skip_beyond) {
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

    // A dispatch's pipeline and the flags ssao_common.glsl reads.
    std::pair<const vk::raii::Pipeline*, std::int32_t> program(ssao::Dispatch dispatch) const {
        using ssao::Dispatch;
        switch (dispatch) {
            case Dispatch::kEstimate:
                return {&hbao_estimate, 0};
            case Dispatch::kFilterX:
                return {&bilateral_filter, 0};
            case Dispatch::kFilterY:
                return {&bilateral_filter, kFlagVertical};
            case Dispatch::kStereoVisibility:
                return {&stereo_visibility, 0};
            case Dispatch::kStereoEstimate:
                return {&stereo_estimate, 0};
            case Dispatch::kStereoReprojectedEstimate:
                return {&stereo_estimate, kFlagReproject};
            case Dispatch::kStereoFilterX:
                return {&bilateral_filter, kFlagStereo};
            case Dispatch::kStereoFilterY:
                return {&bilateral_filter, kFlagStereo | kFlagVertical};
            case Dispatch::kApply:
                break;
        }
        programming_error("SsaoPass::dispatch: the apply is not a compute dispatch");
    }
};

SsaoPass::SsaoPass(const vk_core::Context& ctx) : ctx_(ctx), impl_(std::make_unique<Impl>()) {
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

std::unique_ptr<SsaoBindings> SsaoPass::make_bindings() const {
    auto bindings = std::unique_ptr<SsaoBindings>(new SsaoBindings());
    const std::array pool_sizes = {vk::DescriptorPoolSize(Type::eUniformBuffer, 1),
                                   vk::DescriptorPoolSize(Type::eCombinedImageSampler, 2),
                                   vk::DescriptorPoolSize(Type::eStorageImage, 4)};
    bindings->pool_ = vk::raii::DescriptorPool(
        ctx_.device(), vk::DescriptorPoolCreateInfo(
                           vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 2, pool_sizes));
    const std::array layouts = {*impl_->view_layout, *impl_->apply_layout};
    vk::raii::DescriptorSets sets(ctx_.device(),
                                  vk::DescriptorSetAllocateInfo(*bindings->pool_, layouts));
    bindings->compute_set_ = std::move(sets[0]);
    bindings->apply_set_ = std::move(sets[1]);
    return bindings;
}

void SsaoPass::bind(SsaoBindings& bindings, const SsaoViewImages& images) const {
    MONOPLANE_EXPECTS(images.constants && images.linear_depth && images.ao &&
                      images.scratch.size() == 3);
    MONOPLANE_EXPECTS(images.linear_depth->desc().extent == images.ao->desc().extent);
    MONOPLANE_EXPECTS(images.constants->size() >= sizeof(ViewConstants));
    const vk::DescriptorBufferInfo constants_info(images.constants->handle(), 0,
                                                  sizeof(ViewConstants));
    const vk::DescriptorImageInfo depth_info(*impl_->nearest, images.linear_depth->view(),
                                             executor::layout_for(graph::Use::kSampledCompute));
    const auto storage = [](const vk_core::Image& image) {
        return vk::DescriptorImageInfo(nullptr, image.view(),
                                       executor::layout_for(graph::Use::kStorageWrite));
    };
    // ssao_common.glsl's bindings: L, the raw estimate, the horizontal filter's output, the AO.
    const vk::DescriptorImageInfo other_pixel_info = storage(*images.scratch[2]);
    const vk::DescriptorImageInfo raw_info = storage(*images.scratch[0]);
    const vk::DescriptorImageInfo filtered_info = storage(*images.scratch[1]);
    const vk::DescriptorImageInfo ao_info = storage(*images.ao);
    const vk::DescriptorImageInfo ao_sampled(*impl_->nearest, images.ao->view(),
                                             executor::layout_for(graph::Use::kSampledFragment));
    const vk::DescriptorSet set = *bindings.compute_set_;
    const std::array writes = {
        vk::WriteDescriptorSet(set, 0, 0, Type::eUniformBuffer, {}, constants_info),
        vk::WriteDescriptorSet(set, 1, 0, Type::eCombinedImageSampler, depth_info),
        vk::WriteDescriptorSet(set, 2, 0, Type::eStorageImage, other_pixel_info),
        vk::WriteDescriptorSet(set, 3, 0, Type::eStorageImage, raw_info),
        vk::WriteDescriptorSet(set, 4, 0, Type::eStorageImage, filtered_info),
        vk::WriteDescriptorSet(set, 5, 0, Type::eStorageImage, ao_info),
        vk::WriteDescriptorSet(*bindings.apply_set_, 0, 0, Type::eCombinedImageSampler, ao_sampled),
    };
    ctx_.device().updateDescriptorSets(writes, {});
}

void SsaoPass::dispatch(const vk::raii::CommandBuffer& cmd, ssao::Dispatch dispatch,
                        const SsaoBindings& self, const SsaoBindings& other, vk::Extent2D area,
                        const SsaoParams& params, float skip_beyond) const {
    MONOPLANE_EXPECTS(params.directions > 0 && params.steps > 0 && params.filter_taps > 0);
    MONOPLANE_EXPECTS(params.radius > 0.0f && params.sigma_min > 0.0f &&
                      params.sigma_min <= params.sigma_max);
    const auto [pipeline, flags] = impl_->program(dispatch);
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, **pipeline);
    const std::array sets = {*self.compute_set_, *other.compute_set_};
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *impl_->compute_layout, 0, sets, {});
    cmd.pushConstants<SsaoPush>(*impl_->compute_layout, vk::ShaderStageFlagBits::eCompute, 0,
                                Impl::push(params, area, flags, skip_beyond));
    cmd.dispatch(groups_covering(area.width, kSsaoGroup), groups_covering(area.height, kSsaoGroup),
                 1);
}

float SsaoPass::skip_margin(const SsaoParams& params) {
    // The filter weighs a tap by G_sigma of its world distance, sigma <= sigma_max: at 6 sigma
    // the weight is exp(-18) of the centre's, below any 8-bit level.
    return 6.0f * params.sigma_max;
}

void SsaoPass::apply(const vk::raii::CommandBuffer& cmd, const SsaoBindings& view,
                     const vk_core::Image& hdr, vk::Extent2D area,
                     const vk_core::Image* near_only_depth) const {
    MONOPLANE_EXPECTS(hdr.desc().format == ForwardPass::kHdrFormat);
    MONOPLANE_EXPECTS(!near_only_depth ||
                      near_only_depth->desc().format == ForwardPass::kDepthFormat);
    const Impl& impl = *impl_;
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
                           *view.apply_set_, {});
    const ApplyPush push{static_cast<float>(area.width), static_cast<float>(area.height)};
    cmd.pushConstants<ApplyPush>(*impl.apply_pipeline_layout, vk::ShaderStageFlagBits::eFragment, 0,
                                 push);
    cmd.draw(3, 1, 0, 0);
    cmd.endRendering();
}

}  // namespace monoplane::passes
