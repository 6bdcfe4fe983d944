// The mono-to-stereo composite of each eye (Fink et al. 2019, Sect. 4.2; papers/003 for the
// engine-style copy), a pass kind written as one unit: in the hybrid modes, per eye after C's
// passes, C's image mapped into the eye (eq. 5 through the mono plane, or the far field's integer
// offset) where the eye's depth buffer still holds the cleared far value (no near content), or
// everywhere for the debug view "mono only". It reads C's HDR and linear depth (and, with TAA, C's
// velocity, mapped through eq. 9) and blends into the eye's HDR, linear depth (and velocity).
//
// Where nothing after it reads the eye's HDR image (no TAA, no SSAO of the eyes, no blended
// chunks drawn after it; revise() decides, before the tone mapping is placed), the composite also
// tone maps: one full-screen pass writes the eye's display image whole, C's colour where the eye
// drew nothing and the eye's own HDR colour elsewhere, both through tone_mapping.glsl as the tone
// mapping unit does, and C's linear depth where the eye drew nothing (PlannedPass::
// writes_display). That saves a pass's fixed cost and the HDR image's write and read of every far
// pixel. It needs independentBlend (the second draw writes the display image and leaves the
// linear depth); the tone mapping unit then runs only when the GPU skips the composite.
//
// The declaration (compiled Vulkan-free with MONOPLANE_UNIT_DECLARATION) and the recorder
// (MONOPLANE_UNIT_RECORDER) of renderer/plan/pass_unit.h and renderer/passes/shared/pass_unit.h,
// side by side.
#include "renderer/plan/pass_unit.h"

#ifdef MONOPLANE_UNIT_RECORDER
#include <array>
#include <optional>
#include <vector>

#include "common/programming_error.h"
#include "renderer/executor/image_layouts.h"
#include "renderer/passes/forward/forward_pass.h"
#include "renderer/passes/shared/display_format.h"
#include "renderer/passes/shared/fullscreen_pass.h"
#include "renderer/passes/shared/pass_unit.h"
#include "renderer/passes/shared/slot_sets.h"
#include "renderer/vk/descriptor_set.h"
#include "renderer/vk/pipeline.h"
#endif

namespace monoplane::passes::composite {

#ifdef MONOPLANE_UNIT_DECLARATION
namespace {

using plan::ImageRole;
using plan::ViewId;
using Use = graph::Use;

// The pass's one step, "composite" (any step it had is replaced), with C's images sampled: its
// HDR and linear depth, and with TAA its velocity.
graph::StepBuilder composite_step(plan::PlannedPass& pass, plan::PlanResources& r, bool velocity) {
    pass.steps.assign(1, graph::Step{});
    graph::Step& step = pass.steps.front();
    step.name = "composite";
    graph::StepBuilder uses(step);
    uses.use(r.image(ViewId::kMono, ImageRole::kHdr), Use::kSampledFragment)
        .use(r.image(ViewId::kMono, ImageRole::kLinearDepth), Use::kSampledFragment);
    if (velocity) uses.use(r.image(ViewId::kMono, ImageRole::kVelocity), Use::kSampledFragment);
    return uses;
}

// C shows where the eye drew nothing nearer: depth-tested against the eye, blended into it.
void declare_composite(plan::PlannedPass& pass, plan::PlanResources& r, bool velocity) {
    const ViewId eye = pass.view;
    graph::StepBuilder uses = composite_step(pass, r, velocity);
    uses.use(r.image(eye, ImageRole::kDepth), Use::kDepthTest)
        .use(r.image(eye, ImageRole::kHdr), Use::kColorBlend)
        .use(r.image(eye, ImageRole::kLinearDepth), Use::kColorBlend);
    if (velocity) uses.use(r.image(eye, ImageRole::kVelocity), Use::kColorBlend);
}

// The composite that tone maps: the eye's HDR image only read, its display image written whole.
void declare_display(plan::PlannedPass& pass, plan::PlanResources& r) {
    const ViewId eye = pass.view;
    composite_step(pass, r, false)
        .use(r.image(eye, ImageRole::kHdr), Use::kSampledFragment)
        .use(r.image(eye, ImageRole::kDepth), Use::kDepthTest)
        .use(r.image(eye, ImageRole::kLinearDepth), Use::kColorBlend)
        .use(r.image(eye, ImageRole::kDisplay), Use::kColorWrite);
}

// Per eye in the hybrid modes (the slot is placed in no other); the GPU skips it when C had
// nothing to draw.
void place(plan::UnitPlacement& placement) {
    const bool velocity = placement.options().anti_aliasing == plan::AntiAliasing::kTaa;
    for (ViewId eye : plan::kEyeViews) {
        plan::PlannedPass& pass = placement.add_pass(eye);
        pass.statistics_scope = pass.name;
        declare_composite(pass, placement.resources(), velocity);
        pass.when = placement.when(plan::GpuPredicate::kMonoAny);
        pass.skipped = placement.no_mono_reason();
    }
}

// Fuses the tone mapping into each composite whose eye's HDR image no later pass reads (the
// tone mapping, placed next, would be its only reader).
void revise(plan::UnitPlacement& placement) {
    if (!placement.draws_mono() || placement.options().separate_tonemap ||
        !placement.device().independent_blend) {
        return;
    }
    plan::PlanResources& r = placement.resources();
    for (plan::PlannedPass* pass : placement.own_passes()) {
        if (placement.used_after(*pass, r.image(pass->view, ImageRole::kHdr))) continue;
        pass->writes_display = true;
        declare_display(*pass, r);
    }
}

}  // namespace

plan::PassUnitDeclaration declaration() {
    plan::PassUnitDeclaration unit = plan::built_in_unit(
        plan::PassKind::kComposite, plan::UnitSlot::kComposite,
        "C mapped into each eye in the hybrid modes (eq. 5, or the far field's offset)", &place);
    unit.revise = &revise;
    return unit;
}
#endif  // MONOPLANE_UNIT_DECLARATION

#ifdef MONOPLANE_UNIT_RECORDER
namespace {

const std::uint32_t kCompositeFrag[] = {
#include "composite.frag.spv.inc"
};
const std::uint32_t kCompositeVelocityFrag[] = {
#include "composite_velocity.frag.spv.inc"
};
const std::uint32_t kCompositeDisplayFrag[] = {
#include "composite_display.frag.spv.inc"
};
const std::uint32_t kCompositeNearFrag[] = {
#include "composite_near.frag.spv.inc"
};

// The shader's push-constant block, std430.
struct CompositePush {
    glm::mat4 eye_to_mono;
    glm::vec4 uv_limits;
    glm::vec4 eye_extent_mode;
    glm::vec4 offset_exposure;
    glm::vec4 velocity_scale;
};
static_assert(sizeof(CompositePush) == 128, "must match composite_push.glsl");

constexpr vk::ColorComponentFlags kAllChannels =
    vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
    vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA;

// Begins rendering into `colors` over the eye's depth, read only (the composite's depth test
// against the cleared far value), and sets the viewport to the whole extent.
void begin_over_eye_depth(const vk::raii::CommandBuffer& cmd,
                          vk::ArrayProxy<const vk::RenderingAttachmentInfo> colors,
                          const vk_core::Image& eye_depth, vk::Extent2D extent) {
    const vk::RenderingAttachmentInfo depth(
        eye_depth.view(), executor::layout_for(graph::Use::kDepthTest), {}, {}, {},
        vk::AttachmentLoadOp::eLoad, vk::AttachmentStoreOp::eStore);
    cmd.beginRendering(vk::RenderingInfo()
                           .setRenderArea(vk::Rect2D({0, 0}, extent))
                           .setLayerCount(1)
                           .setColorAttachments(colors)
                           .setPDepthAttachment(&depth));
    vk_core::set_viewport_and_scissor(cmd, extent);
}

// A colour attachment kept where the draw does not write (the composite blends into the eye).
vk::RenderingAttachmentInfo loaded(const vk_core::Image& image) {
    return vk::RenderingAttachmentInfo()
        .setImageView(image.view())
        .setImageLayout(executor::layout_for(graph::Use::kColorBlend))
        .setLoadOp(vk::AttachmentLoadOp::eLoad)
        .setStoreOp(vk::AttachmentStoreOp::eStore);
}

class CompositeRecorder final : public UnitRecorder {
  public:
    CompositeRecorder(const vk_core::Context& ctx, const UnitPasses& passes);

    void record(UnitRecording& r) override {
        const plan::ViewId eye = r.pass().view;
        const CompositeValues& values = r.values().composite;
        if (r.pass().writes_display) {
            record_display(r, eye, values);
        } else {
            record_blend(r, eye, values);
        }
    }

  private:
    void make_blend_pipelines(vk_core::GraphicsPipelineDesc desc);
    void make_display_pipelines(vk_core::GraphicsPipelineDesc desc);
    vk::DescriptorSet mono_set(UnitRecording& r, plan::ViewId eye);
    vk::DescriptorSet eye_set(UnitRecording& r, plan::ViewId eye);
    void push(const vk::raii::CommandBuffer& cmd, vk::PipelineLayout layout, vk::Extent2D extent,
              const CompositeValues& values, plan::ViewId eye, float exposure) const;
    void record_blend(UnitRecording& r, plan::ViewId eye, const CompositeValues& values);
    void record_display(UnitRecording& r, plan::ViewId eye, const CompositeValues& values);

    const vk_core::Context& ctx_;
    bool velocity_;  // TAA: C's velocity mapped into the eye's
    vk::raii::Sampler bilinear_{nullptr};
    vk::raii::Sampler nearest_{nullptr};
    // Set 0: C's images. Binding 2 (C's velocity) exists only with velocity: every binding of a
    // set must be written before it is bound, and lavapipe reads every one.
    vk::raii::DescriptorSetLayout mono_layout_{nullptr};
    std::optional<SlotSets> mono_sets_;
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline behind_near_content_{nullptr};  // depth test: equal to the cleared far
    vk::raii::Pipeline everywhere_{nullptr};
    // The composite that tone maps: set 0 C's images as above, set 1 the eye's HDR image.
    vk::raii::DescriptorSetLayout eye_layout_{nullptr};
    std::optional<SlotSets> eye_sets_;
    vk::raii::PipelineLayout display_layout_{nullptr};
    vk::raii::Pipeline display_behind_near_content_{nullptr};
    vk::raii::Pipeline display_everywhere_{nullptr};
    vk::raii::Pipeline near_display_{nullptr};  // depth not equal to the cleared far value
};

// The pipelines of the passes the renderer may plan: the blending composite's (with velocity
// under TAA; made always, as a frame whose composite cannot tone map may come in any mode), and
// the tone-mapping composite's where a possible plan fuses them.
CompositeRecorder::CompositeRecorder(const vk_core::Context& ctx, const UnitPasses& passes)
    : ctx_(ctx),
      velocity_(passes.any_declares(plan::ViewId::kMono, plan::ImageRole::kVelocity)),
      bilinear_(vk_core::make_clamped_sampler(ctx, vk::Filter::eLinear)),
      nearest_(vk_core::make_clamped_sampler(ctx, vk::Filter::eNearest)) {
    std::vector<vk::DescriptorSetLayoutBinding> bindings;
    for (std::uint32_t binding = 0; binding < (velocity_ ? 3u : 2u); ++binding) {
        bindings.emplace_back(binding, vk::DescriptorType::eCombinedImageSampler, 1,
                              vk::ShaderStageFlagBits::eFragment);
    }
    mono_layout_ = vk::raii::DescriptorSetLayout(ctx.device(),
                                                 vk::DescriptorSetLayoutCreateInfo({}, bindings));
    mono_sets_.emplace(ctx, *mono_layout_,
                       std::vector{vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler,
                                                          velocity_ ? 3u : 2u)});
    const vk::raii::ShaderModule vert = make_fullscreen_vertex_shader(ctx);
    vk_core::GraphicsPipelineDesc desc;
    desc.vertex = *vert;
    desc.depth_format = ForwardPass::kDepthFormat;
    desc.cull = vk::CullModeFlagBits::eNone;
    desc.depth_write = false;
    // The full-screen triangle lies at depth 0, the eye's far plane (m): equal only where the
    // eye drew nothing.
    desc.depth_compare = vk::CompareOp::eEqual;
    const bool displays = passes.any([](const plan::PlannedPass& p) { return p.writes_display; });
    // TAA reads the eye's HDR image after the composite: it never tone maps then.
    MONOPLANE_EXPECTS(!(velocity_ && displays));
    make_blend_pipelines(desc);
    if (displays) make_display_pipelines(desc);
}

void CompositeRecorder::make_blend_pipelines(vk_core::GraphicsPipelineDesc desc) {
    const vk::DescriptorSetLayout set_layout = *mono_layout_;
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eFragment, 0, sizeof(CompositePush));
    layout_ =
        vk::raii::PipelineLayout(ctx_.device(), vk::PipelineLayoutCreateInfo({}, set_layout, push));
    const vk::raii::ShaderModule frag = velocity_
                                            ? vk_core::make_shader(ctx_, kCompositeVelocityFrag)
                                            : vk_core::make_shader(ctx_, kCompositeFrag);
    desc.layout = *layout_;
    desc.fragment = *frag;
    desc.color_formats = {ForwardPass::kHdrFormat, ForwardPass::kLinearDepthFormat};
    if (velocity_) desc.color_formats.push_back(ForwardPass::kVelocityFormat);
    behind_near_content_ = vk_core::make_graphics_pipeline(ctx_, desc);
    desc.depth_test = false;
    everywhere_ = vk_core::make_graphics_pipeline(ctx_, desc);
}

void CompositeRecorder::make_display_pipelines(vk_core::GraphicsPipelineDesc desc) {
    const vk::DescriptorSetLayoutBinding binding(0, vk::DescriptorType::eCombinedImageSampler, 1,
                                                 vk::ShaderStageFlagBits::eFragment);
    eye_layout_ = vk::raii::DescriptorSetLayout(ctx_.device(),
                                                vk::DescriptorSetLayoutCreateInfo({}, binding));
    eye_sets_.emplace(
        ctx_, *eye_layout_,
        std::vector{vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 1)});
    const std::array set_layouts = {*mono_layout_, *eye_layout_};
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eFragment, 0, sizeof(CompositePush));
    display_layout_ = vk::raii::PipelineLayout(ctx_.device(),
                                               vk::PipelineLayoutCreateInfo({}, set_layouts, push));
    const vk::raii::ShaderModule composite = vk_core::make_shader(ctx_, kCompositeDisplayFrag);
    const vk::raii::ShaderModule near = vk_core::make_shader(ctx_, kCompositeNearFrag);
    desc.layout = *display_layout_;
    desc.fragment = *composite;
    desc.color_formats = {kDisplayFormat, ForwardPass::kLinearDepthFormat};
    display_behind_near_content_ = vk_core::make_graphics_pipeline(ctx_, desc);
    desc.depth_test = false;
    display_everywhere_ = vk_core::make_graphics_pipeline(ctx_, desc);
    // The complement of the composite's test: every pixel the eye drew. Its linear depth is the
    // eye's own and stays; only the display image is written.
    desc.fragment = *near;
    desc.depth_test = true;
    desc.depth_compare = vk::CompareOp::eNotEqual;
    desc.color_write_masks = {kAllChannels, vk::ColorComponentFlags()};
    near_display_ = vk_core::make_graphics_pipeline(ctx_, desc);
}

// The slot's set of C's images for the eye's pass (C's images are remade when C grows).
vk::DescriptorSet CompositeRecorder::mono_set(UnitRecording& r, plan::ViewId eye) {
    const vk::DescriptorSet set = mono_sets_->at(r.values().slot, eye);
    const auto read_only = executor::layout_for(graph::Use::kSampledFragment);
    std::vector images = {
        vk::DescriptorImageInfo(
            *bilinear_, r.image(plan::ViewId::kMono, plan::ImageRole::kHdr).view(), read_only),
        vk::DescriptorImageInfo(*nearest_,
                                r.image(plan::ViewId::kMono, plan::ImageRole::kLinearDepth).view(),
                                read_only),
    };
    if (velocity_) {
        images.emplace_back(
            *nearest_, r.image(plan::ViewId::kMono, plan::ImageRole::kVelocity).view(), read_only);
    }
    vk_core::write_sampled_images(ctx_, set, images);
    return set;
}

// The slot's set of the eye's HDR image, read texel-exact by the composite that tone maps.
vk::DescriptorSet CompositeRecorder::eye_set(UnitRecording& r, plan::ViewId eye) {
    const vk::DescriptorSet set = eye_sets_->at(r.values().slot, eye);
    const std::array images = {
        vk::DescriptorImageInfo(*nearest_, r.image(eye, plan::ImageRole::kHdr).view(),
                                executor::layout_for(graph::Use::kSampledFragment))};
    vk_core::write_sampled_images(ctx_, set, images);
    return set;
}

void CompositeRecorder::push(const vk::raii::CommandBuffer& cmd, vk::PipelineLayout layout,
                             vk::Extent2D extent, const CompositeValues& values, plan::ViewId eye,
                             float exposure) const {
    const CompositeEyeMapping& mapping = values.eyes[plan::eye_index(eye)];
    const glm::vec2 half_texel = 0.5f / values.mono_allocation;
    const CompositePush block{
        mapping.eye_to_mono,
        glm::vec4(mapping.uv_scale, half_texel),
        glm::vec4(static_cast<float>(extent.width), static_cast<float>(extent.height),
                  static_cast<float>(values.mapping), values.tint),
        glm::vec4(static_cast<float>(mapping.pixel_offset.x),
                  static_cast<float>(mapping.pixel_offset.y), exposure, 0.0f),
        glm::vec4(mapping.velocity_scale, 0.0f, 0.0f),
    };
    cmd.pushConstants<CompositePush>(layout, vk::ShaderStageFlagBits::eFragment, 0, block);
}

// Appends to the eye's HDR, linear depth (and velocity): their contents are kept.
void CompositeRecorder::record_blend(UnitRecording& r, plan::ViewId eye,
                                     const CompositeValues& values) {
    const vk::DescriptorSet set = mono_set(r, eye);
    const vk_core::Image& hdr = r.image(eye, plan::ImageRole::kHdr);
    const vk::Extent2D extent = hdr.desc().extent;
    std::vector colors = {loaded(hdr), loaded(r.image(eye, plan::ImageRole::kLinearDepth))};
    if (velocity_) colors.push_back(loaded(r.image(eye, plan::ImageRole::kVelocity)));
    const vk::raii::CommandBuffer& cmd = r.cmd();
    begin_over_eye_depth(cmd, colors, r.image(eye, plan::ImageRole::kDepth), extent);
    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics,
                     values.cover_all_pixels ? *everywhere_ : *behind_near_content_);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 0, set, {});
    push(cmd, *layout_, extent, values, eye, 0.0f);
    with_predicate(cmd, r.predicate(r.pass().when), [&] { cmd.draw(3, 1, 0, 0); });
    cmd.endRendering();
}

// Writes every pixel of the display image once (tone mapped as the tone mapping unit does) and
// C's linear depth where the eye drew nothing; the eye's HDR image is only read. Where the GPU
// skips both draws the display image is undefined, and the eye's tone mapping writes it.
void CompositeRecorder::record_display(UnitRecording& r, plan::ViewId eye,
                                       const CompositeValues& values) {
    const std::array sets = {mono_set(r, eye), eye_set(r, eye)};
    const vk_core::Image& display = r.image(eye, plan::ImageRole::kDisplay);
    const vk::Extent2D extent = display.desc().extent;
    // Every pixel is written by one of the two draws: the display image's contents need no load.
    const std::array colors = {
        vk::RenderingAttachmentInfo(display.view(), executor::layout_for(graph::Use::kColorWrite),
                                    vk::ResolveModeFlagBits::eNone, nullptr, {},
                                    vk::AttachmentLoadOp::eDontCare, vk::AttachmentStoreOp::eStore),
        loaded(r.image(eye, plan::ImageRole::kLinearDepth))};
    const vk::raii::CommandBuffer& cmd = r.cmd();
    begin_over_eye_depth(cmd, colors, r.image(eye, plan::ImageRole::kDepth), extent);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *display_layout_, 0, sets, {});
    push(cmd, *display_layout_, extent, values, eye, r.values().settings.tonemap.exposure);
    with_predicate(cmd, r.predicate(r.pass().when), [&] {
        cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, values.cover_all_pixels
                                                               ? *display_everywhere_
                                                               : *display_behind_near_content_);
        cmd.draw(3, 1, 0, 0);
        if (values.cover_all_pixels) return;
        cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *near_display_);
        cmd.draw(3, 1, 0, 0);
    });
    cmd.endRendering();
}

}  // namespace

std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx, const UnitScene&,
                                            const UnitPasses& passes, const UnitSettings&) {
    return std::make_unique<CompositeRecorder>(ctx, passes);
}
#endif  // MONOPLANE_UNIT_RECORDER

}  // namespace monoplane::passes::composite
