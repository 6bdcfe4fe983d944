#include "renderer/modes/mode_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <initializer_list>
#include <utility>

#include "common/result.h"
#include "renderer/modes/farfield_rig.h"
#include "renderer/modes/frustum_culling.h"
#include "renderer/passes/culling/cull_constants.h"
#include "renderer/rig/temporal_jitter.h"

namespace monoplane::modes {
namespace {

using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;

constexpr vk::ImageUsageFlags kColorTarget = vk::ImageUsageFlagBits::eColorAttachment |
                                             vk::ImageUsageFlagBits::eSampled |
                                             vk::ImageUsageFlagBits::eTransferSrc;

// The region whose shadows are computed: the scene, clipped to a box around the viewer, snapped
// to a coarse grid so small head motion does not invalidate the shadow map.
scenes::Aabb shadow_region(const scenes::Scene& scene, const glm::dvec3& head, float radius) {
    const double snap = radius / 4.0;
    const glm::dvec3 centre = glm::round(head / snap) * snap;
    scenes::Aabb region = scene.bounds;
    region.min = glm::max(region.min, glm::vec3(centre - glm::dvec3(radius)));
    region.max = glm::min(region.max, glm::vec3(centre + glm::dvec3(radius)));
    region.max = glm::max(region.max, region.min);
    return region;
}

glm::dvec3 to_world(const rig::Pose& head, const glm::dvec3& in_head) {
    return glm::dvec3(rig::to_matrix(head) * glm::dvec4(in_head, 1.0));
}

void copy_to_buffer(const vk::raii::CommandBuffer& cmd, const vk_core::Image& image,
                    vk::Extent2D extent, const vk_core::Buffer& buffer, vk::ImageLayout from) {
    vk_core::transition(cmd, image, from, vk::ImageLayout::eTransferSrcOptimal,
                        Stage::eColorAttachmentOutput | Stage::eFragmentShader,
                        Access::eColorAttachmentWrite, Stage::eTransfer, Access::eTransferRead);
    cmd.copyImageToBuffer(
        image.handle(), vk::ImageLayout::eTransferSrcOptimal, buffer.handle(),
        vk::BufferImageCopy(
            0, 0, 0,
            vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, image.base_layer(), 1),
            {0, 0, 0}, vk::Extent3D(extent, 1)));
}

// The forward pass's step for a planned draw (one to one).
passes::ForwardStep forward_step(DrawStep step) {
    switch (step) {
        case DrawStep::kMaskHidden:
            return passes::ForwardStep::kMaskHidden;
        case DrawStep::kDepthPrepass:
            return passes::ForwardStep::kDepthPrepass;
        case DrawStep::kChunks:
            return passes::ForwardStep::kChunks;
        case DrawStep::kChunksShowRouting:
            return passes::ForwardStep::kChunksShowRouting;
        case DrawStep::kSky:
            return passes::ForwardStep::kSky;
    }
    return passes::ForwardStep::kChunks;
}

void to_shader_read(const vk::raii::CommandBuffer& cmd, const vk_core::Image& image) {
    vk_core::transition(cmd, image, vk::ImageLayout::eColorAttachmentOptimal,
                        vk::ImageLayout::eShaderReadOnlyOptimal, Stage::eColorAttachmentOutput,
                        Access::eColorAttachmentWrite, Stage::eFragmentShader,
                        Access::eShaderSampledRead);
}

}  // namespace

vk::SampleCountFlagBits msaa_samples(AntiAliasing aa) {
    switch (aa) {
        case AntiAliasing::kMsaa2:
            return vk::SampleCountFlagBits::e2;
        case AntiAliasing::kMsaa4:
            return vk::SampleCountFlagBits::e4;
        case AntiAliasing::kMsaa8:
            return vk::SampleCountFlagBits::e8;
        default:
            return vk::SampleCountFlagBits::e1;
    }
}

// What a view's targets must support beyond the basic forward pass.
struct ViewFeatures {
    bool velocity = false;  // TAA: velocity, and (eyes) two history images
    bool history = false;
    vk::SampleCountFlagBits samples = vk::SampleCountFlagBits::e1;
};

// The images a forward pass writes: one camera's, or both eyes' as two-layer images (single-pass
// stereo), or one layer of those. Not movable: multisample refers to its own members.
struct ModeRenderer::ForwardImages {
    vk_core::Image hdr;
    vk_core::Image depth;
    vk_core::Image linear_depth;
    // TAA: screen-space velocity.
    std::optional<vk_core::Image> velocity;
    // MSAA: the multisampled targets the forward pass resolves into hdr and linear_depth.
    std::optional<vk_core::Image> hdr_samples;
    std::optional<vk_core::Image> linear_depth_samples;
    std::optional<vk_core::Image> depth_samples;
    std::optional<passes::MultisampleTargets> multisample;

    ForwardImages(const vk_core::Context& ctx, vk::Extent2D size, const ViewFeatures& features,
                  std::uint32_t layers)
        : hdr(ctx, {size, passes::ForwardPass::kHdrFormat, kColorTarget, layers}),
          // Sampled: the merged depth pyramid reads the eyes' depth.
          depth(ctx,
                {size, passes::ForwardPass::kDepthFormat,
                 vk::ImageUsageFlagBits::eDepthStencilAttachment | vk::ImageUsageFlagBits::eSampled,
                 layers}),
          linear_depth(ctx, {size, passes::ForwardPass::kLinearDepthFormat, kColorTarget, layers}) {
        if (features.velocity) {
            velocity.emplace(ctx, vk_core::ImageDesc{size, passes::ForwardPass::kVelocityFormat,
                                                     vk::ImageUsageFlagBits::eColorAttachment |
                                                         vk::ImageUsageFlagBits::eSampled,
                                                     layers});
        }
        if (features.samples != vk::SampleCountFlagBits::e1) {
            // Transient: only their resolve is kept.
            const vk::ImageUsageFlags usage = vk::ImageUsageFlagBits::eColorAttachment |
                                              vk::ImageUsageFlagBits::eTransientAttachment;
            hdr_samples.emplace(ctx, vk_core::ImageDesc{size, passes::ForwardPass::kHdrFormat,
                                                        usage, layers, features.samples});
            linear_depth_samples.emplace(
                ctx, vk_core::ImageDesc{size, passes::ForwardPass::kLinearDepthFormat, usage,
                                        layers, features.samples});
            depth_samples.emplace(
                ctx, vk_core::ImageDesc{size, passes::ForwardPass::kDepthFormat,
                                        vk::ImageUsageFlagBits::eDepthStencilAttachment |
                                            vk::ImageUsageFlagBits::eTransientAttachment,
                                        layers, features.samples});
            multisample.emplace(
                passes::MultisampleTargets{*hdr_samples, *linear_depth_samples, *depth_samples});
        }
    }

    // One layer of `both` (which must outlive it): what an eye's later passes read and write. The
    // multisampled images are not viewed per layer: only the single pass draws into them.
    ForwardImages(const vk_core::Context& ctx, const ForwardImages& both, std::uint32_t layer)
        : hdr(vk_core::Image::layer_of(ctx, both.hdr, layer)),
          depth(vk_core::Image::layer_of(ctx, both.depth, layer)),
          linear_depth(vk_core::Image::layer_of(ctx, both.linear_depth, layer)) {
        if (both.velocity) velocity = vk_core::Image::layer_of(ctx, *both.velocity, layer);
    }

    ForwardImages(const ForwardImages&) = delete;
    ForwardImages& operator=(const ForwardImages&) = delete;

    passes::ForwardTargets forward_targets(vk::Extent2D area, bool clear_color = false) const {
        return {hdr,
                depth,
                linear_depth,
                area,
                clear_color,
                velocity ? &*velocity : nullptr,
                multisample ? &*multisample : nullptr};
    }
};

// The targets and per-frame data of one camera. With single-pass stereo the eyes' forward images
// are the layers of one set of two-layer images (ModeRenderer::eye_layers_).
namespace {

// What a camera owns beyond its forward images: its tone-mapped image, its constants, its
// read-back buffers and, under TAA, its two history images (this frame's output and the last).
struct ViewOutputs {
    vk_core::Image display;
    vk_core::Buffer constants;
    vk_core::Buffer readback;
    vk_core::Buffer depth_readback;
    std::array<std::optional<vk_core::Image>, 2> history;

    ViewOutputs(const vk_core::Context& ctx, vk::Extent2D size, const ViewFeatures& features)
        : display(ctx, {size, passes::TonemapPass::kDisplayFormat, kColorTarget}),
          constants(ctx, sizeof(passes::ViewConstants), vk::BufferUsageFlagBits::eUniformBuffer,
                    vk_core::MemoryUse::kHostVisible),
          readback(ctx, vk::DeviceSize{size.width} * size.height * 4,
                   vk::BufferUsageFlagBits::eTransferDst, vk_core::MemoryUse::kHostVisible),
          depth_readback(ctx, vk::DeviceSize{size.width} * size.height * 4,
                         vk::BufferUsageFlagBits::eTransferDst, vk_core::MemoryUse::kHostVisible) {
        if (!features.history) return;
        for (auto& image : history) {
            image.emplace(ctx, vk_core::ImageDesc{size, passes::TaaPass::kOutputFormat,
                                                  vk::ImageUsageFlagBits::eColorAttachment |
                                                      vk::ImageUsageFlagBits::eSampled});
        }
    }
};

}  // namespace

struct ModeRenderer::View : ForwardImages, ViewOutputs {
    vk::Extent2D extent;                        // the images' size (C: its allocation)
    vk::Extent2D area;                          // the region drawn (C: its viewport, eq. 8)
    passes::ViewConstants written_constants{};  // what constants holds this frame
    vk_core::DescriptorSet forward_set;
    vk_core::DescriptorSet tonemap_set;
    RgbaImage image;
    std::vector<float> linear;
    // TAA: the sets reading and writing the history images.
    std::array<vk_core::DescriptorSet, 2> taa_sets;
    std::array<vk_core::DescriptorSet, 2> tonemap_taa_sets;
    glm::dmat4 previous_unjittered{1.0};  // last frame's world -> clip without jitter
    bool has_previous = false;
    std::unique_ptr<passes::SsaoView> ssao;
    std::vector<float> ao;
    EyeFrameGeometry geometry;

    // A camera with forward images of its own (C, and the eyes of two-pass stereo).
    View(const vk_core::Context& ctx, vk::Extent2D size, const ViewFeatures& features)
        : ForwardImages(ctx, size, features, 1),
          ViewOutputs(ctx, size, features),
          extent(size),
          area(size) {}

    // An eye: layer `layer` of both eyes' forward images.
    View(const vk_core::Context& ctx, const ForwardImages& both, std::uint32_t layer,
         const ViewFeatures& features)
        : ForwardImages(ctx, both, layer),
          ViewOutputs(ctx, both.hdr.desc().extent, features),
          extent(both.hdr.desc().extent),
          area(extent) {}

    passes::ForwardTargets forward_targets(bool clear_color = false) const {
        return ForwardImages::forward_targets(area, clear_color);
    }
};

struct ModeRenderer::MonoView : View {
    vk_core::DescriptorSet composite_set;
    using View::View;
};

namespace {

// Refuses shared scene resources made for other shadow parameters than the renderer's.
std::shared_ptr<SceneResources> checked(std::shared_ptr<SceneResources> resources,
                                        const RendererOptions& options) {
    if (!(resources->shadow_params() == options.shadow)) {
        throw UserError(
            "a renderer's shadow parameters differ from those its scene's shared "
            "resources were made with: make one SceneResources per shadow setting");
    }
    return resources;
}

// Refuses option combinations the renderer does not implement, with the reason.
const RendererOptions& checked(const vk_core::Context& ctx, Mode mode,
                               const RendererOptions& options) {
    const vk::SampleCountFlagBits samples = msaa_samples(options.anti_aliasing);
    if (samples != vk::SampleCountFlagBits::e1) {
        if (mode != Mode::kStereo) {
            throw UserError("MSAA (" + anti_aliasing_name(options.anti_aliasing) +
                            ") is available in stereo mode only: in the hybrid modes C's image "
                            "is mapped into the eyes after the resolve would have happened "
                            "(papers/000 Sect. 4.5; docs/hybrid.md). Use --anti-aliasing taa.");
        }
        const vk::PhysicalDeviceLimits limits = ctx.physical_device().getProperties().limits;
        const vk::SampleCountFlags supported =
            limits.framebufferColorSampleCounts & limits.framebufferDepthSampleCounts;
        if (!(supported & samples)) {
            throw UserError(anti_aliasing_name(options.anti_aliasing) + " is not supported by " +
                            ctx.device_info().name);
        }
    }
    if (options.read_back_ao && !options.ssao) {
        throw UserError("reading back ambient occlusion needs SSAO switched on");
    }
    return options;
}

}  // namespace

ModeRenderer::ModeRenderer(const vk_core::Context& ctx, const scenes::Scene& scene, Mode mode,
                           vk::Extent2D eye_extent, const RendererOptions& options,
                           double nearest_mono_plane)
    : ModeRenderer(ctx, std::make_shared<SceneResources>(ctx, scene, options.shadow), mode,
                   eye_extent, options, nearest_mono_plane) {}

ModeRenderer::ModeRenderer(const vk_core::Context& ctx, std::shared_ptr<SceneResources> resources,
                           Mode mode, vk::Extent2D eye_extent, const RendererOptions& options,
                           double nearest_mono_plane)
    : ctx_(ctx),
      resources_(checked(std::move(resources), options)),
      scene_(resources_->scene()),
      mode_(mode),
      eye_extent_(eye_extent),
      options_(checked(ctx, mode, options)),
      nearest_mono_plane_(nearest_mono_plane),
      forward_(ctx, passes::ForwardConfig{options.anti_aliasing == AntiAliasing::kTaa,
                                          msaa_samples(options.anti_aliasing),
                                          passes::StereoDuplication::kNone, options.vertex_work}),
      tonemap_(ctx),
      composite_(ctx, options.anti_aliasing == AntiAliasing::kTaa),
      culling_(ctx, scene_, resources_->chunk_table()),
      pyramid_(ctx),
      taa_(ctx),
      profiler_(ctx) {
    if (options.ssao) ssao_ = std::make_unique<passes::SsaoPass>(ctx, options.ssao_params);
    merged_depth_set_ = forward_.make_merged_depth_set();
    const bool taa = options.anti_aliasing == AntiAliasing::kTaa;
    const ViewFeatures eye_features{taa, taa, msaa_samples(options.anti_aliasing)};
    if (options.stereo_pass != StereoPass::kTwoPasses) {
        eye_layers_ = std::make_unique<ForwardImages>(ctx, eye_extent, eye_features, 2);
        const passes::StereoDuplication duplication =
            options.stereo_pass == StereoPass::kMultiview
                ? passes::StereoDuplication::kMultiview
                : passes::StereoDuplication::kGeometryShader;
        eyes_forward_ = std::make_unique<passes::ForwardPass>(
            ctx, passes::ForwardConfig{taa, msaa_samples(options.anti_aliasing), duplication,
                                       options.vertex_work});
        eye_pair_constants_.emplace(ctx, 2 * sizeof(passes::ViewConstants),
                                    vk::BufferUsageFlagBits::eUniformBuffer,
                                    vk_core::MemoryUse::kHostVisible);
        eye_pair_set_ = eyes_forward_->make_view_set(
            *eye_pair_constants_, resources_->shadow().view(), resources_->shadow().sampler());
    }
    for (std::uint32_t e = 0; e < 2; ++e) {
        auto& eye = eyes_[e];
        // Two passes draw into images of each eye's own: lavapipe (Mesa 22.3) does not resolve
        // MSAA into a layer other than 0 of a layered image.
        eye = eye_layers_ ? std::make_unique<View>(ctx, *eye_layers_, e, eye_features)
                          : std::make_unique<View>(ctx, eye_extent, eye_features);
        make_view_sets(*eye);
        if (taa) make_taa_sets(*eye);
        if (ssao_) eye->ssao = ssao_->make_view(eye->constants, eye->linear_depth, eye_extent);
    }
    pyramid_.set_eye_depths(eyes_[0]->depth.view(), eyes_[1]->depth.view(), eye_extent_);
    culling_.set_merged_depth(pyramid_.view(), pyramid_.sampler());
    forward_.write_merged_depth(merged_depth_set_, pyramid_.view(), pyramid_.sampler(),
                                culling_.routing());
}

void ModeRenderer::make_taa_sets(View& view) const {
    for (int parity = 0; parity < 2; ++parity) {
        // Parity p writes history[p] and reads history[1 - p].
        view.taa_sets[parity] = taa_.make_inputs(view.hdr, *view.velocity, view.linear_depth,
                                                 *view.history[1 - parity]);
        view.tonemap_taa_sets[parity] = tonemap_.make_input(*view.history[parity]);
    }
}

void ModeRenderer::ensure_pyramid() {
    if (!pyramid_.resize(mono_->extent)) return;
    pyramid_.set_eye_depths(eyes_[0]->depth.view(), eyes_[1]->depth.view(), eye_extent_);
    culling_.set_merged_depth(pyramid_.view(), pyramid_.sampler());
    forward_.write_merged_depth(merged_depth_set_, pyramid_.view(), pyramid_.sampler(),
                                culling_.routing());
}

void ModeRenderer::make_view_sets(View& view) const {
    view.forward_set = forward_.make_view_set(view.constants, resources_->shadow().view(),
                                              resources_->shadow().sampler());
    view.tonemap_set = tonemap_.make_input(view.hdr);
}

ModeRenderer::~ModeRenderer() = default;

void ModeRenderer::ensure_mono_view(int width, int height) {
    const vk::Extent2D needed(static_cast<std::uint32_t>(width),
                              static_cast<std::uint32_t>(height));
    if (mono_ && mono_->extent.width >= needed.width && mono_->extent.height >= needed.height) {
        return;
    }
    // Allocated once for the nearest m in normal use (eq. 8); grown only if a frame needs more.
    mono_.reset();
    const bool taa = options_.anti_aliasing == AntiAliasing::kTaa;
    mono_ = std::make_unique<MonoView>(ctx_, needed, ViewFeatures{taa, false});
    make_view_sets(*mono_);
    mono_->composite_set =
        composite_.make_source(mono_->hdr, mono_->linear_depth, taa ? &*mono_->velocity : nullptr);
    if (ssao_) mono_->ssao = ssao_->make_view(mono_->constants, mono_->linear_depth, needed);
}

void ModeRenderer::update_view(View& view, const glm::dmat4& view_proj,
                               const glm::dmat4& unjittered, const glm::dvec3& position,
                               const FrameInputs& inputs, const glm::dvec3& mono_position,
                               double blend_band, const glm::dmat4& light_view_proj,
                               double hidden_depth_threshold) {
    const scenes::Lighting& lighting = scene_.lighting;
    const rig::Pose& head = inputs.views.head;
    passes::ViewConstants c{};
    c.view_proj = glm::mat4(view_proj);
    c.inv_view_proj = glm::mat4(glm::inverse(view_proj));
    c.light_view_proj = glm::mat4(light_view_proj);
    c.camera_position = glm::vec4(glm::vec3(position), 1.0f);
    c.sun_direction = glm::vec4(glm::normalize(lighting.sun_direction), 0.0f);
    c.sun_radiance = glm::vec4(lighting.sun_radiance, 0.0f);
    c.sky_zenith = glm::vec4(lighting.sky_zenith, 0.0f);
    c.sky_horizon = glm::vec4(lighting.sky_horizon, 0.0f);
    c.ground_albedo = glm::vec4(lighting.ground_albedo, 0.0f);
    c.shadow_params = glm::vec4(resources_->shadow().texel_size(), 0.0f, 0.0f, 0.0f);
    c.head_position = glm::vec4(glm::vec3(head.position), 1.0f);
    c.head_forward =
        glm::vec4(glm::vec3(glm::normalize(head.orientation * glm::dvec3(0.0, 0.0, -1.0))), 0.0f);
    c.mono_camera_position = glm::vec4(glm::vec3(mono_position), 1.0f);
    c.view_blend = glm::vec4(static_cast<float>(inputs.mono_plane), static_cast<float>(blend_band),
                             static_cast<float>(hidden_depth_threshold), 0.0f);
    c.velocity_view_proj = glm::mat4(unjittered);
    // A restarted history has no previous frame: zero velocity.
    const bool continues = history_valid_ && view.has_previous;
    c.prev_view_proj = glm::mat4(continues ? view.previous_unjittered : unjittered);
    view.constants.write(&c, sizeof(c));
    view.written_constants = c;
    view.previous_unjittered = unjittered;
    view.has_previous = true;
    view.geometry = {view_proj, position};
}

void ModeRenderer::decide_routing(const FrameInputs& inputs, passes::CullFrame& cull) const {
    if (!rig_ || rig_->mono_skipped) return;  // stereo draws everything in the eyes
    const scenes::ChunkRouting& routing = scene_.routing;
    const glm::dvec3 head = inputs.views.head.position;
    const double m = inputs.mono_plane;
    // Force-mono geometry lies outside a vertical cylinder of radius R: from an eye it is at
    // least R - |eye_xz| away, and at most the frustum's widest angle theta off the view axis,
    // so its depth in front of the eyes is at least (R - |eye_xz|) cos(theta). Honoured only when
    // that is beyond m: C, starting at m - eps, then draws every pixel of it the eyes would have.
    if (routing.force_mono_outside_radius > 0.0f) {
        double cos_widest = 1.0;
        for (const rig::Tangents& t : {inputs.views.left, inputs.views.right}) {
            const double tan_x = std::max(std::abs(t.left), std::abs(t.right));
            const double tan_y = std::max(std::abs(t.down), std::abs(t.up));
            cos_widest = std::min(cos_widest, 1.0 / std::sqrt(1.0 + tan_x * tan_x + tan_y * tan_y));
        }
        const double clearance = routing.force_mono_outside_radius -
                                 glm::length(glm::dvec2(head.x, head.z)) - 0.5 * inputs.views.ipd;
        cull.honour_force_mono = clearance * cos_widest >= m;
    }
    // Force-stereo geometry lies inside a sphere: at most |head - centre| + r from the head, so
    // nearer than C's near plane m - eps when that bound is.
    if (routing.force_stereo_inside_radius > 0.0f) {
        const double reach = glm::length(head - glm::dvec3(routing.force_stereo_centre)) +
                             routing.force_stereo_inside_radius + 0.5 * inputs.views.ipd;
        cull.honour_force_stereo = reach <= m - rig_->overlap;
    }
}

// This frame's decisions and matrices, made before anything is recorded and read by every pass
// recorder (the plan says which passes run; this says with what).
struct ModeRenderer::FrameState {
    const FrameInputs* inputs = nullptr;
    bool taa = false;
    bool use_mono = false;  // C is drawn (a hybrid mode with something beyond m - eps)
    std::optional<FarfieldRig> farfield;
    glm::dvec2 jitter_px{0.0};
    glm::dmat4 eye_jitter{1.0};
    glm::dmat4 mono_jitter{1.0};
    glm::dmat4 light_view_proj{1.0};
    bool shadow_needed = false;
    bool predicated = false;  // GPU predicates (VK_EXT_conditional_rendering)
    // FrameInputs::mono_culling resolved (kAuto: the chooser's pick for this frame).
    MonoCulling mono_culling = MonoCulling::kNoOpt;
    bool measuring_variant = false;  // this frame's time goes to the chooser
    // Colour images a pass left as attachments that a later pass samples (frame_plan.h's
    // resource names): transitioned once, before their first reader.
    std::vector<std::string> attachments_written;
};

ModeRenderer::FrameState ModeRenderer::prepare_frame(const FrameInputs& inputs) {
    FrameState frame;
    frame.inputs = &inputs;
    const StereoViewInputs& views = inputs.views;

    // TAA: this frame's jitter, and whether the history continues (consecutive frames of the
    // same configuration; a study switching between renderers restarts it).
    frame.taa = options_.anti_aliasing == AntiAliasing::kTaa;
    const std::uint64_t frame_index = inputs.frame_index.value_or(next_frame_index_);
    history_valid_ = frame.taa && frame_index == next_frame_index_ && frame_index > 0 &&
                     history_mono_plane_ == inputs.mono_plane;
    next_frame_index_ = frame_index + 1;
    history_mono_plane_ = inputs.mono_plane;
    frame.jitter_px = frame.taa ? rig::halton_jitter(frame_index) : glm::dvec2(0.0);
    frame.eye_jitter =
        rig::jitter_matrix(frame.jitter_px, glm::dvec2(eye_extent_.width, eye_extent_.height));

    const scenes::Aabb region =
        shadow_region(scene_, views.head.position, options_.shadow.region_radius_m);
    frame.light_view_proj =
        passes::fit_light_view_proj(glm::dvec3(scene_.lighting.sun_direction), region);
    frame.shadow_needed = resources_->shadow_needed(frame.light_view_proj);
    frame.predicated = ctx_.capabilities().conditional_rendering;

    build_frame_rig(inputs, frame);
    resolve_variant(inputs, frame);
    update_frame_views(inputs, frame);
    return frame;
}

void ModeRenderer::resolve_variant(const FrameInputs& inputs, FrameState& frame) {
    frame.mono_culling = inputs.mono_culling;
    if (inputs.mono_culling != MonoCulling::kAuto) return;
    // Only monoplane's hybrid drawing C has variants to tell apart.
    if (mode_ != Mode::kHybrid || !frame.use_mono) {
        frame.mono_culling = MonoCulling::kNoOpt;
        return;
    }
    // Another m changes what the pyramid saves: measure again.
    if (variant_mono_plane_ != inputs.mono_plane) variant_chooser_.reset();
    variant_mono_plane_ = inputs.mono_plane;
    frame.mono_culling = variant_chooser_.next();
    frame.measuring_variant = true;
}

void ModeRenderer::build_frame_rig(const FrameInputs& inputs, FrameState& frame) {
    // The rig (hybrid modes). m >= f leaves C out and hybrid records the stereo pass list.
    rig_.reset();
    if (mode_ == Mode::kStereo) return;
    const StereoViewInputs& views = inputs.views;
    rig::RigInputs rig_inputs;
    rig_inputs.eyes = {views.left, views.right};
    rig_inputs.eye_width = static_cast<int>(eye_extent_.width);
    rig_inputs.eye_height = static_cast<int>(eye_extent_.height);
    rig_inputs.ipd = views.ipd;
    rig_inputs.mono_plane = inputs.mono_plane;
    rig_inputs.near = views.near;
    rig_inputs.far = views.far;
    rig_inputs.overlap_k = inputs.overlap_k;
    if (nearest_mono_plane_ > 0.0 && nearest_mono_plane_ <= inputs.mono_plane) {
        rig_inputs.nearest_mono_plane = nearest_mono_plane_;
    }
    rig_ = rig::build_rig(rig_inputs).value_or_throw();
    frame.use_mono = !rig_->mono_skipped;
    if (frame.use_mono && mode_ == Mode::kHybridFarfield) {
        frame.farfield =
            build_farfield_rig(rig_inputs.eyes, rig_inputs.eye_width, rig_inputs.eye_height,
                               views.ipd, inputs.mono_plane, views.far);
    }
}

void ModeRenderer::update_frame_views(const FrameInputs& inputs, FrameState& frame) {
    const StereoViewInputs& views = inputs.views;
    const bool use_mono = frame.use_mono;
    const auto& farfield = frame.farfield;
    // C's work saved by the merged depth pyramid (the plan's rule, renderer/plan/frame_plan.cpp).
    const bool depth_tested = use_mono && !farfield && frame.mono_culling != MonoCulling::kNoOpt &&
                              inputs.debug != DebugView::kMonoOnly;
    passes::CullFrame cull;
    const glm::dvec3 mono_in_head = farfield || !use_mono ? glm::dvec3(0.0) : rig_->mono_position;
    const glm::dvec3 mono_position = to_world(views.head, mono_in_head);
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        const int e = static_cast<int>(eye);
        const glm::dvec3 offset = eye_offset(eye, views.ipd);
        const glm::dmat4 view_proj =
            use_mono ? rig_->eye_projection[e] * rig::view_matrix(views.head, offset)
                     : eye_view_proj(views, eye);
        const double band = use_mono && !farfield ? inputs.view_blend_band : 0.0;
        update_view(*eyes_[e], frame.eye_jitter * view_proj, view_proj,
                    to_world(views.head, offset), inputs, mono_position, band,
                    frame.light_view_proj);
        cull.view_proj[e] = view_proj;  // a sub-pixel jitter changes no chunk's visibility
    }
    if (use_mono) {
        glm::dmat4 mono_view_proj;
        if (farfield) {
            ensure_mono_view(farfield->width, farfield->height);
            mono_->area = mono_->extent;
            mono_view_proj = farfield->projection * rig::view_matrix(views.head, mono_in_head);
        } else {
            ensure_mono_view(rig_->mono.allocated_width, rig_->mono.allocated_height);
            mono_->area = vk::Extent2D(static_cast<std::uint32_t>(rig_->mono.viewport_width),
                                       static_cast<std::uint32_t>(rig_->mono.viewport_height));
            mono_view_proj = rig_->mono_projection * rig::view_matrix(views.head, mono_in_head);
        }
        // The eyes' reversed-Z depth of m - eps (Sect. 4.4: z_m): a pyramid value above it
        // means every eye pixel reading that part of C shows nearer content.
        const glm::dvec4 plane = rig_->eye_projection[0] *
                                 glm::dvec4(0.0, 0.0, -(inputs.mono_plane - rig_->overlap), 1.0);
        const double threshold = plane.z / plane.w;
        // The same jitter in C's pixels (Sect. 4.5).
        frame.mono_jitter =
            rig::jitter_matrix(frame.jitter_px, glm::dvec2(mono_->area.width, mono_->area.height));
        update_view(*mono_, frame.mono_jitter * mono_view_proj, mono_view_proj, mono_position,
                    inputs, mono_position, 0.0, frame.light_view_proj, threshold);
        cull.view_proj[MONOPLANE_CULL_MONO] = mono_view_proj;
        cull.mono_viewport = glm::dvec2(mono_->area.width, mono_->area.height);
        cull.hidden_depth_threshold = threshold;
        decide_routing(inputs, cull);
        if (depth_tested) {
            ensure_pyramid();
            cull.pyramid_mips = pyramid_.mips();
        }
    }
    // Nearest chunks first (one order for every view: the eyes and C look from the head).
    cull.draw_order = front_to_back_order(scene_, views.head.position);
    culling_.set_frame(cull);
    if (eye_pair_constants_) {
        // view_block.glsl's views[2]: left, then right (std140 arrays of this struct are packed).
        const std::array pair = {eyes_[0]->written_constants, eyes_[1]->written_constants};
        eye_pair_constants_->write(pair.data(), sizeof(pair));
    }
}

FramePlan ModeRenderer::plan(const FrameInputs& inputs, const FrameState& frame) const {
    PlanOptions options;
    options.mode = mode_;
    options.stereo_pass = options_.stereo_pass;
    options.anti_aliasing = options_.anti_aliasing;
    options.ssao = options_.ssao.has_value();
    options.depth_prepass = options_.depth_prepass;
    options.read_back = options_.read_back;
    options.read_back_depth = options_.read_back_depth;
    options.read_back_ao = options_.read_back_ao;
    options.read_back_draw_lists = options_.read_back_draw_lists;
    PlanFrame planned;
    planned.mono_skipped = !frame.use_mono;
    planned.mono_culling = frame.mono_culling;
    planned.debug = inputs.debug;
    planned.shadow_needed = frame.shadow_needed;
    return plan_frame(options, planned, PlanDevice{frame.predicated});
}

profile::FrameStats ModeRenderer::render_frame(
    const FrameInputs& inputs,
    const std::function<void(const vk::raii::CommandBuffer&)>& record_after) {
    const auto cpu_start = std::chrono::steady_clock::now();
    FrameState frame = prepare_frame(inputs);
    last_plan_ = plan(inputs, frame);

    double record_ms = 0.0;
    ctx_.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
        profiler_.begin_frame(cmd);
        for (const PlannedPass* pass : last_plan_.executed()) record_pass(cmd, *pass, frame);
        record_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpu_start)
                .count();
        if (record_after) record_after(cmd);
    });
    mono_rendered_ = frame.use_mono && options_.read_back;
    if (frame.taa) history_parity_ = 1 - history_parity_;
    last_variant_ = frame.mono_culling;
    profile::FrameStats stats = collect_frame(record_ms, frame.use_mono);
    if (frame.measuring_variant) variant_chooser_.record(stats.gpu_frame_ms);
    return stats;
}

const vk_core::Image* ModeRenderer::planned_image(const std::string& resource) const {
    const std::size_t dot = resource.find('.');
    if (dot == std::string::npos) return nullptr;
    const std::string view = resource.substr(0, dot);
    const std::string image = resource.substr(dot + 1);
    const View* owner = view == "left"    ? eyes_[0].get()
                        : view == "right" ? eyes_[1].get()
                        : view == "mono"  ? mono_.get()
                                          : nullptr;
    if (owner == nullptr) return nullptr;
    if (image == "hdr") return &owner->hdr;
    if (image == "linear_depth") return &owner->linear_depth;
    if (image == "velocity") return owner->velocity ? &*owner->velocity : nullptr;
    return nullptr;  // depth, history, ao, display: their passes transition them
}

void ModeRenderer::record_pass(const vk::raii::CommandBuffer& cmd, const PlannedPass& pass,
                               FrameState& frame) {
    // The plan's reads: colour images an earlier pass left as attachments become sampled.
    for (const std::string& read : pass.reads) {
        auto written =
            std::find(frame.attachments_written.begin(), frame.attachments_written.end(), read);
        if (written == frame.attachments_written.end()) continue;
        if (const vk_core::Image* image = planned_image(read)) to_shader_read(cmd, *image);
        frame.attachments_written.erase(written);
    }
    const bool timed = pass.kind != PassKind::kReadback;  // read-backs are not GPU frame time
    if (timed) profiler_.begin_pass(cmd, pass.name);
    if (!pass.statistics_scope.empty()) profiler_.begin_view(cmd, pass.statistics_scope);
    record_planned(cmd, pass, frame);
    if (!pass.statistics_scope.empty()) profiler_.end_view(cmd);
    if (timed) profiler_.end_pass(cmd);
    // The plan's writes: what this pass left as colour attachments.
    for (const std::string& write : pass.writes) {
        if (planned_image(write) != nullptr &&
            std::find(frame.attachments_written.begin(), frame.attachments_written.end(), write) ==
                frame.attachments_written.end()) {
            frame.attachments_written.push_back(write);
        }
    }
}

std::optional<passes::Predicate> ModeRenderer::predicate(GpuPredicate when) const {
    switch (when) {
        case GpuPredicate::kAlways:
            return std::nullopt;
        case GpuPredicate::kMonoAny:
            return culling_.predicate(MONOPLANE_PRED_MONO_ANY, false);
        case GpuPredicate::kMonoNone:
            return culling_.predicate(MONOPLANE_PRED_MONO_ANY, true);
        case GpuPredicate::kMonoDepthTested:
            return culling_.predicate(MONOPLANE_PRED_MONO_DEPTH_TESTED, false);
    }
    return std::nullopt;
}

void ModeRenderer::record_planned(const vk::raii::CommandBuffer& cmd, const PlannedPass& pass,
                                  const FrameState& frame) {
    switch (pass.kind) {
        case PassKind::kCulling:
            culling_.record_frustum_phase(cmd);
            break;
        case PassKind::kShadow:
            resources_->record_shadow(cmd, frame.light_view_proj);
            break;
        case PassKind::kForward:
            record_forward(cmd, pass);
            break;
        case PassKind::kDepthPyramid:
            record_pyramid(cmd, pass, frame);
            break;
        case PassKind::kOcclusionCulling:
            passes::with_predicate(cmd, predicate(pass.when),
                                   [&] { culling_.record_occlusion_phase(cmd); });
            break;
        case PassKind::kMonoSsao:
            // The far region's AO, computed once for both eyes (C alone sees it).
            passes::with_predicate(cmd, predicate(pass.when), [&] {
                ssao_->record_view(cmd, *mono_->ssao, mono_->area);
                ssao_->record_apply(cmd, *mono_->ssao, mono_->hdr, mono_->area);
            });
            break;
        case PassKind::kComposite:
            record_composite(cmd, pass, frame);
            break;
        case PassKind::kSsao:
            // In hybrid, pixels well beyond m take C's AO: their own estimate is not needed.
            ssao_->record_pair(
                cmd, *eyes_[0]->ssao, *eyes_[1]->ssao, eye_extent_, *options_.ssao,
                frame.use_mono ? static_cast<float>(frame.inputs->mono_plane) + ssao_->skip_margin()
                               : passes::SsaoPass::kEveryPixel);
            for (const auto& eye : eyes_) {
                // In hybrid the far region already carries C's AO: only the near content takes
                // the eyes'.
                ssao_->record_apply(cmd, *eye->ssao, eye->hdr, eye_extent_,
                                    frame.use_mono ? &eye->depth : nullptr);
            }
            break;
        case PassKind::kTaa:
            record_taa(cmd, *eyes_[pass.view == "left" ? 0 : 1]);
            break;
        case PassKind::kTonemap:
            record_tonemap(cmd, pass, frame);
            break;
        case PassKind::kReadback:
            record_readback(cmd, frame);
            break;
    }
}

void ModeRenderer::record_forward(const vk::raii::CommandBuffer& cmd, const PlannedPass& pass) {
    std::vector<passes::ForwardDraw> draws;
    for (const PlannedDraw& draw : pass.draws) {
        draws.push_back({forward_step(draw.step), predicate(draw.when)});
    }
    if (pass.view == "eyes") {
        // Both eyes in one pass, from the list of chunks either eye needs.
        eyes_forward_->record(cmd, eye_layers_->forward_targets(eye_extent_), *eye_pair_set_,
                              *merged_depth_set_, resources_->geometry(),
                              culling_.draws(passes::CullView::kBothEyes), draws);
        return;
    }
    if (pass.view == "mono") {
        // Pixels hidden in both eyes stay unwritten; C's image read back shows them black,
        // and C's SSAO must not read stale depths there.
        const bool masked = std::any_of(pass.draws.begin(), pass.draws.end(), [](const auto& d) {
            return d.step == DrawStep::kMaskHidden;
        });
        const bool clear_color = masked && (options_.read_back || ssao_);
        forward_.record(cmd, mono_->forward_targets(clear_color), *mono_->forward_set,
                        *merged_depth_set_, resources_->geometry(),
                        culling_.draws(passes::CullView::kMono), draws);
        return;
    }
    const int e = pass.view == "left" ? 0 : 1;
    forward_.record(cmd, eyes_[e]->forward_targets(), *eyes_[e]->forward_set, *merged_depth_set_,
                    resources_->geometry(), culling_.draws(static_cast<passes::CullView>(e)),
                    draws);
}

void ModeRenderer::record_pyramid(const vk::raii::CommandBuffer& cmd, const PlannedPass& pass,
                                  const FrameState& frame) {
    for (const auto& eye : eyes_) {
        vk_core::transition(cmd, eye->depth, vk::ImageLayout::eDepthAttachmentOptimal,
                            vk::ImageLayout::eDepthReadOnlyOptimal, Stage::eLateFragmentTests,
                            Access::eDepthStencilAttachmentWrite, Stage::eComputeShader,
                            Access::eShaderSampledRead);
    }
    std::array<glm::dmat3, 2> mono_to_eye;
    for (int e = 0; e < 2; ++e) {
        mono_to_eye[e] =
            rig::jittered_pixel_mapping(rig::mono_pixel_to_eye_pixel(*rig_, e), frame.jitter_px);
    }
    pyramid_.record(cmd, mono_to_eye, predicate(pass.when));
    for (const auto& eye : eyes_) {
        vk_core::transition(cmd, eye->depth, vk::ImageLayout::eDepthReadOnlyOptimal,
                            vk::ImageLayout::eDepthAttachmentOptimal, Stage::eComputeShader,
                            Access::eShaderSampledRead,
                            Stage::eEarlyFragmentTests | Stage::eLateFragmentTests,
                            Access::eDepthStencilAttachmentRead);
    }
}

void ModeRenderer::record_composite(const vk::raii::CommandBuffer& cmd, const PlannedPass& pass,
                                    const FrameState& frame) {
    const FrameInputs& inputs = *frame.inputs;
    const int e = pass.view == "left" ? 0 : 1;
    const View& view = *eyes_[e];
    passes::CompositeParams params;
    params.mono_allocation = glm::vec2(static_cast<float>(mono_->extent.width),
                                       static_cast<float>(mono_->extent.height));
    if (frame.farfield) {
        params.mapping = passes::CompositeMapping::kOffsetCopy;
        params.pixel_offset = frame.farfield->offsets[e];
        // Same pixel size: NDC velocities scale with the images' widths.
        params.velocity_scale = glm::vec2(
            static_cast<float>(mono_->area.width) / static_cast<float>(eye_extent_.width),
            static_cast<float>(mono_->area.height) / static_cast<float>(eye_extent_.height));
    } else {
        // Eq. 5 between the jittered clip spaces: C's image and the eye's are both displaced by
        // the jitter, so the mapping undoes one and applies the other.
        params.eye_to_mono =
            glm::mat4(frame.mono_jitter * rig_->eye_to_mono[e] * glm::inverse(frame.eye_jitter));
        params.velocity_scale = glm::vec2(rig::mono_velocity_to_eye(*rig_, e));
        // C's image is valid in [0, viewport / allocation] (Sect. 4.2). The image may be larger
        // than the rig's own allocation: it was sized for an earlier m.
        params.uv_scale = glm::vec2(static_cast<float>(mono_->area.width),
                                    static_cast<float>(mono_->area.height)) /
                          params.mono_allocation;
    }
    if (inputs.debug == DebugView::kTintMono) params.tint = 1.0f;
    if (inputs.debug == DebugView::kStereoOnly) params.mapping = passes::CompositeMapping::kNothing;
    params.cover_all_pixels = inputs.debug == DebugView::kMonoOnly;
    params.when = predicate(pass.when);
    composite_.record(
        cmd, {view.hdr, view.linear_depth, view.depth, view.velocity ? &*view.velocity : nullptr},
        *mono_->composite_set, params);
}

void ModeRenderer::record_tonemap(const vk::raii::CommandBuffer& cmd, const PlannedPass& pass,
                                  const FrameState& frame) {
    if (pass.view == "mono") {
        tonemap_.record(cmd, mono_->display, *mono_->tonemap_set, options_.tonemap);
        return;
    }
    const View& view = *eyes_[pass.view == "left" ? 0 : 1];
    const vk::DescriptorSet input =
        frame.taa ? *view.tonemap_taa_sets[history_parity_] : *view.tonemap_set;
    tonemap_.record(cmd, view.display, input, options_.tonemap);
}

void ModeRenderer::record_readback(const vk::raii::CommandBuffer& cmd, const FrameState& frame) {
    for (const auto& view : eyes_) {
        if (options_.read_back) {
            copy_to_buffer(cmd, view->display, view->extent, view->readback,
                           vk::ImageLayout::eColorAttachmentOptimal);
        }
        if (options_.read_back_depth) {
            copy_to_buffer(cmd, view->linear_depth, view->extent, view->depth_readback,
                           vk::ImageLayout::eShaderReadOnlyOptimal);
        }
        if (options_.read_back_ao) ssao_->record_readback(cmd, *view->ssao);
    }
    if (frame.use_mono && options_.read_back) {
        copy_to_buffer(cmd, mono_->display, mono_->area, mono_->readback,
                       vk::ImageLayout::eColorAttachmentOptimal);
    }
    culling_.record_readback(cmd, options_.read_back_draw_lists);
}

profile::FrameStats ModeRenderer::collect_frame(double record_ms, bool use_mono) {
    profile::FrameStats stats = profiler_.collect();
    stats.cpu_record_ms = record_ms;
    const auto counts = culling_.counts();
    for (profile::ViewStatistics& view : stats.views) {
        if (view.view == "left") view.draws = counts[MONOPLANE_COUNT_LEFT];
        if (view.view == "right") view.draws = counts[MONOPLANE_COUNT_RIGHT];
        if (view.view == "eyes") view.draws = counts[MONOPLANE_COUNT_BOTH_EYES];
        if (view.view == "mono") {
            view.draws = counts[MONOPLANE_COUNT_MONO];
            view.draws_before_occlusion_culling = counts[MONOPLANE_COUNT_MONO_CANDIDATES];
        }
    }
    auto read_image = [](const View& view, vk::Extent2D extent, RgbaImage& image) {
        image.width = extent.width;
        image.height = extent.height;
        const auto* bytes = reinterpret_cast<const std::uint8_t*>(view.readback.mapped());
        image.pixels.assign(bytes, bytes + std::size_t{extent.width} * extent.height * 4);
    };
    if (options_.read_back) {
        for (auto& eye : eyes_) read_image(*eye, eye->extent, eye->image);
        if (use_mono) read_image(*mono_, mono_->area, mono_->image);
    }
    if (options_.read_back_ao) {
        for (auto& eye : eyes_) eye->ao = eye->ssao->ao_values();
    }
    if (options_.read_back_depth) {
        for (auto& eye : eyes_) {
            const auto* values = reinterpret_cast<const float*>(eye->depth_readback.mapped());
            eye->linear.assign(values,
                               values + std::size_t{eye->extent.width} * eye->extent.height);
        }
    }
    return stats;
}

void ModeRenderer::record_taa(const vk::raii::CommandBuffer& cmd, View& view) {
    const vk_core::Image& history = *view.history[1 - history_parity_];
    if (!history_valid_) {
        // Never written (or stale): bound for the shader's interface, not read on a reset.
        vk_core::transition(cmd, history, vk::ImageLayout::eUndefined,
                            vk::ImageLayout::eShaderReadOnlyOptimal, Stage::eFragmentShader,
                            Access::eShaderSampledRead, Stage::eFragmentShader,
                            Access::eShaderSampledRead);
    }
    const vk_core::Image& output = *view.history[history_parity_];
    taa_.record(cmd, output, *view.taa_sets[history_parity_], options_.taa, !history_valid_);
    to_shader_read(cmd, output);
}

std::vector<std::uint32_t> ModeRenderer::drawn_chunks(passes::CullView view) const {
    // Without the option the lists were never copied to the host: nothing to report.
    if (!options_.read_back_draw_lists) return {};
    return culling_.drawn_chunks(view);
}

const vk_core::Image& ModeRenderer::display_image(Eye eye) const {
    return eyes_[static_cast<int>(eye)]->display;
}

const RgbaImage& ModeRenderer::eye_image(Eye eye) const {
    return eyes_[static_cast<int>(eye)]->image;
}

const RgbaImage* ModeRenderer::mono_image() const {
    return mono_rendered_ && mono_ ? &mono_->image : nullptr;
}

const std::vector<float>& ModeRenderer::eye_linear_depth(Eye eye) const {
    return eyes_[static_cast<int>(eye)]->linear;
}

const std::vector<float>& ModeRenderer::eye_ao(Eye eye) const {
    return eyes_[static_cast<int>(eye)]->ao;
}

const EyeFrameGeometry& ModeRenderer::eye_geometry(Eye eye) const {
    return eyes_[static_cast<int>(eye)]->geometry;
}

}  // namespace monoplane::modes
