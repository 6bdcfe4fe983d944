#include "renderer/modes/mode_renderer.h"

#include <chrono>
#include <cmath>

#include "common/result.h"
#include "renderer/modes/farfield_rig.h"
#include "renderer/passes/culling/cull_constants.h"

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
                    vk::Extent2D extent, const vk_core::Buffer& buffer) {
    vk_core::transition(cmd, image, vk::ImageLayout::eColorAttachmentOptimal,
                        vk::ImageLayout::eTransferSrcOptimal, Stage::eColorAttachmentOutput,
                        Access::eColorAttachmentWrite, Stage::eTransfer, Access::eTransferRead);
    cmd.copyImageToBuffer(
        image.handle(), vk::ImageLayout::eTransferSrcOptimal, buffer.handle(),
        vk::BufferImageCopy(0, 0, 0,
                            vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, 0, 1),
                            {0, 0, 0}, vk::Extent3D(extent, 1)));
}

void to_shader_read(const vk::raii::CommandBuffer& cmd, const vk_core::Image& image) {
    vk_core::transition(cmd, image, vk::ImageLayout::eColorAttachmentOptimal,
                        vk::ImageLayout::eShaderReadOnlyOptimal, Stage::eColorAttachmentOutput,
                        Access::eColorAttachmentWrite, Stage::eFragmentShader,
                        Access::eShaderSampledRead);
}

}  // namespace

std::optional<Mode> parse_mode(const std::string& name) {
    if (name == "stereo") return Mode::kStereo;
    if (name == "hybrid") return Mode::kHybrid;
    if (name == "hybrid-farfield") return Mode::kHybridFarfield;
    return std::nullopt;
}

std::string mode_name(Mode mode) {
    switch (mode) {
        case Mode::kStereo:
            return "stereo";
        case Mode::kHybrid:
            return "hybrid";
        case Mode::kHybridFarfield:
            return "hybrid-farfield";
    }
    return "?";
}

std::optional<DebugView> parse_debug_view(const std::string& name) {
    if (name == "none") return DebugView::kNone;
    if (name == "tint-mono") return DebugView::kTintMono;
    if (name == "stereo-only") return DebugView::kStereoOnly;
    if (name == "mono-only") return DebugView::kMonoOnly;
    if (name == "routing") return DebugView::kRouting;
    return std::nullopt;
}

std::optional<MonoCulling> parse_mono_culling(const std::string& name) {
    if (name == "no-opt") return MonoCulling::kNoOpt;
    if (name == "discard") return MonoCulling::kDiscard;
    if (name == "occlusion-cull") return MonoCulling::kOcclusionCull;
    return std::nullopt;
}

std::string mono_culling_name(MonoCulling culling) {
    switch (culling) {
        case MonoCulling::kNoOpt:
            return "no-opt";
        case MonoCulling::kDiscard:
            return "discard";
        case MonoCulling::kOcclusionCull:
            return "occlusion-cull";
    }
    return "?";
}

// The targets and per-frame data of one camera.
struct ModeRenderer::View {
    vk::Extent2D extent;  // the images' size (C: its allocation)
    vk::Extent2D area;    // the region drawn (C: its viewport, eq. 8)
    vk_core::Image hdr;
    vk_core::Image depth;
    vk_core::Image linear_depth;
    vk_core::Image display;
    vk_core::Buffer constants;
    vk_core::Buffer readback;
    vk_core::Buffer depth_readback;
    vk::raii::DescriptorSet forward_set{nullptr};
    vk::raii::DescriptorSet tonemap_set{nullptr};
    RgbaImage image;
    std::vector<float> linear;

    View(const vk_core::Context& ctx, vk::Extent2D size)
        : extent(size),
          area(size),
          hdr(ctx, {size, passes::ForwardPass::kHdrFormat, kColorTarget}),
          // Sampled: the merged depth pyramid reads the eyes' depth.
          depth(ctx, {size, passes::ForwardPass::kDepthFormat,
                      vk::ImageUsageFlagBits::eDepthStencilAttachment |
                          vk::ImageUsageFlagBits::eSampled}),
          linear_depth(ctx, {size, passes::ForwardPass::kLinearDepthFormat, kColorTarget}),
          display(ctx, {size, passes::TonemapPass::kDisplayFormat, kColorTarget}),
          constants(ctx, sizeof(passes::ViewConstants), vk::BufferUsageFlagBits::eUniformBuffer,
                    vk_core::MemoryUse::kHostVisible),
          readback(ctx, vk::DeviceSize{size.width} * size.height * 4,
                   vk::BufferUsageFlagBits::eTransferDst, vk_core::MemoryUse::kHostVisible),
          depth_readback(ctx, vk::DeviceSize{size.width} * size.height * 4,
                         vk::BufferUsageFlagBits::eTransferDst, vk_core::MemoryUse::kHostVisible) {}

    passes::ForwardTargets forward_targets(bool clear_color = false) const {
        return {hdr, depth, linear_depth, area, clear_color};
    }
};

struct ModeRenderer::MonoView : View {
    vk::raii::DescriptorSet composite_set{nullptr};
    using View::View;
};

ModeRenderer::ModeRenderer(const vk_core::Context& ctx, const scenes::Scene& scene, Mode mode,
                           vk::Extent2D eye_extent, const RendererOptions& options,
                           double nearest_mono_plane)
    : ctx_(ctx),
      scene_(scene),
      mode_(mode),
      eye_extent_(eye_extent),
      options_(options),
      nearest_mono_plane_(nearest_mono_plane),
      geometry_(ctx, scene),
      shadow_(ctx, options.shadow),
      forward_(ctx),
      tonemap_(ctx),
      composite_(ctx),
      shadow_draws_(ctx, scene.chunks.size()),
      culling_(ctx, scene),
      pyramid_(ctx),
      profiler_(ctx) {
    const std::array pool_sizes = {
        vk::DescriptorPoolSize(vk::DescriptorType::eUniformBuffer, 3),
        vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 9),
        vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, 1),
    };
    descriptor_pool_ = vk::raii::DescriptorPool(
        ctx.device(), vk::DescriptorPoolCreateInfo(
                          vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 8, pool_sizes));
    const vk::DescriptorSetLayout merged_depth_layout = forward_.merged_depth_layout();
    merged_depth_set_ = std::move(vk::raii::DescriptorSets(
        ctx.device(), vk::DescriptorSetAllocateInfo(*descriptor_pool_, merged_depth_layout))[0]);
    for (auto& eye : eyes_) {
        eye = std::make_unique<View>(ctx, eye_extent);
        const std::array layouts = {forward_.set_layout(), tonemap_.set_layout()};
        vk::raii::DescriptorSets sets(ctx.device(),
                                      vk::DescriptorSetAllocateInfo(*descriptor_pool_, layouts));
        eye->forward_set = std::move(sets[0]);
        eye->tonemap_set = std::move(sets[1]);
        write_view_sets(*eye);
    }
    std::vector<std::uint32_t> all(scene.chunks.size());
    for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    shadow_draws_.assign(scene, all);
    pyramid_.set_eye_depths(eyes_[0]->depth.view(), eyes_[1]->depth.view(), eye_extent_);
    culling_.set_merged_depth(pyramid_.view(), pyramid_.sampler());
    write_merged_depth_set();
}

void ModeRenderer::ensure_pyramid() {
    if (!pyramid_.resize(mono_->extent)) return;
    pyramid_.set_eye_depths(eyes_[0]->depth.view(), eyes_[1]->depth.view(), eye_extent_);
    culling_.set_merged_depth(pyramid_.view(), pyramid_.sampler());
    write_merged_depth_set();
}

void ModeRenderer::write_merged_depth_set() const {
    const vk::DescriptorImageInfo merged(pyramid_.sampler(), pyramid_.view(),
                                         vk::ImageLayout::eGeneral);
    const vk::DescriptorBufferInfo routing(culling_.routing(), 0, VK_WHOLE_SIZE);
    const std::array writes = {
        vk::WriteDescriptorSet(*merged_depth_set_, 0, 0, vk::DescriptorType::eCombinedImageSampler,
                               merged),
        vk::WriteDescriptorSet(*merged_depth_set_, 1, 0, vk::DescriptorType::eStorageBuffer, {},
                               routing),
    };
    ctx_.device().updateDescriptorSets(writes, {});
}

void ModeRenderer::write_view_sets(const View& view) const {
    const vk::DescriptorBufferInfo constants_info(view.constants.handle(), 0, VK_WHOLE_SIZE);
    const vk::DescriptorImageInfo shadow_info(shadow_.sampler(), shadow_.view(),
                                              vk::ImageLayout::eShaderReadOnlyOptimal);
    const vk::DescriptorImageInfo hdr_info(tonemap_.sampler(), view.hdr.view(),
                                           vk::ImageLayout::eShaderReadOnlyOptimal);
    const std::array writes = {
        vk::WriteDescriptorSet(*view.forward_set, 0, 0, vk::DescriptorType::eUniformBuffer, {},
                               constants_info),
        vk::WriteDescriptorSet(*view.forward_set, 1, 0, vk::DescriptorType::eCombinedImageSampler,
                               shadow_info),
        vk::WriteDescriptorSet(*view.tonemap_set, 0, 0, vk::DescriptorType::eCombinedImageSampler,
                               hdr_info),
    };
    ctx_.device().updateDescriptorSets(writes, {});
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
    mono_ = std::make_unique<MonoView>(ctx_, needed);
    const std::array layouts = {forward_.set_layout(), tonemap_.set_layout(),
                                composite_.set_layout()};
    vk::raii::DescriptorSets sets(ctx_.device(),
                                  vk::DescriptorSetAllocateInfo(*descriptor_pool_, layouts));
    mono_->forward_set = std::move(sets[0]);
    mono_->tonemap_set = std::move(sets[1]);
    mono_->composite_set = std::move(sets[2]);
    write_view_sets(*mono_);
    const vk::DescriptorImageInfo bilinear_hdr(composite_.bilinear_sampler(), mono_->hdr.view(),
                                               vk::ImageLayout::eShaderReadOnlyOptimal);
    const vk::DescriptorImageInfo linear_info(composite_.nearest_sampler(),
                                              mono_->linear_depth.view(),
                                              vk::ImageLayout::eShaderReadOnlyOptimal);
    const std::array writes = {
        vk::WriteDescriptorSet(*mono_->composite_set, 0, 0,
                               vk::DescriptorType::eCombinedImageSampler, bilinear_hdr),
        vk::WriteDescriptorSet(*mono_->composite_set, 1, 0,
                               vk::DescriptorType::eCombinedImageSampler, linear_info),
    };
    ctx_.device().updateDescriptorSets(writes, {});
}

void ModeRenderer::update_view(View& view, const glm::dmat4& view_proj, const glm::dvec3& position,
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
    c.shadow_params = glm::vec4(shadow_.texel_size(), 0.0f, 0.0f, 0.0f);
    c.head_position = glm::vec4(glm::vec3(head.position), 1.0f);
    c.head_forward =
        glm::vec4(glm::vec3(glm::normalize(head.orientation * glm::dvec3(0.0, 0.0, -1.0))), 0.0f);
    c.mono_camera_position = glm::vec4(glm::vec3(mono_position), 1.0f);
    c.view_blend = glm::vec4(static_cast<float>(inputs.mono_plane), static_cast<float>(blend_band),
                             static_cast<float>(hidden_depth_threshold), 0.0f);
    view.constants.write(&c, sizeof(c));
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

profile::FrameStats ModeRenderer::render_frame(
    const FrameInputs& inputs,
    const std::function<void(const vk::raii::CommandBuffer&)>& record_after) {
    const auto cpu_start = std::chrono::steady_clock::now();
    const StereoViewInputs& views = inputs.views;

    const scenes::Aabb region =
        shadow_region(scene_, views.head.position, options_.shadow.region_radius_m);
    const glm::dmat4 light_view_proj =
        passes::fit_light_view_proj(glm::dvec3(scene_.lighting.sun_direction), region);
    const bool shadow_needed = shadow_light_view_proj_ != light_view_proj;

    // The rig (hybrid modes). m >= f leaves C out and hybrid records the stereo pass list.
    bool use_mono = false;
    std::optional<FarfieldRig> farfield;
    rig_.reset();
    if (mode_ != Mode::kStereo) {
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
        use_mono = !rig_->mono_skipped;
        if (use_mono && mode_ == Mode::kHybridFarfield) {
            farfield =
                build_farfield_rig(rig_inputs.eyes, rig_inputs.eye_width, rig_inputs.eye_height,
                                   views.ipd, inputs.mono_plane, views.far);
        }
    }
    // C's work saved by the merged depth pyramid: monoplane's hybrid only (the far field's
    // offset copy is another mapping), and never in the debug views that show C's whole image.
    const bool depth_tested = use_mono && !farfield && inputs.mono_culling != MonoCulling::kNoOpt &&
                              inputs.debug != DebugView::kMonoOnly;
    const bool occlusion_culled =
        depth_tested && inputs.mono_culling == MonoCulling::kOcclusionCull;

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
        update_view(*eyes_[e], view_proj, to_world(views.head, offset), inputs, mono_position, band,
                    light_view_proj);
        cull.view_proj[e] = view_proj;
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
        update_view(*mono_, mono_view_proj, mono_position, inputs, mono_position, 0.0,
                    light_view_proj, threshold);
        cull.view_proj[MONOPLANE_CULL_MONO] = mono_view_proj;
        cull.mono_viewport = glm::dvec2(mono_->area.width, mono_->area.height);
        cull.hidden_depth_threshold = threshold;
        decide_routing(inputs, cull);
        if (depth_tested) {
            ensure_pyramid();
            cull.pyramid_mips = pyramid_.mips();
        }
    }
    culling_.set_frame(cull);

    // GPU predicates (VK_EXT_conditional_rendering) where the device has them; without, every
    // pass runs and relies on empty draw counts alone.
    const bool predicated = ctx_.capabilities().conditional_rendering;
    auto when = [&](std::uint32_t word, bool inverted = false) -> std::optional<passes::Predicate> {
        if (!predicated) return std::nullopt;
        return culling_.predicate(word, inverted);
    };
    std::vector<passes::ForwardDraw> eye_steps = {{passes::ForwardStep::kChunks, std::nullopt}};
    if (!use_mono) {
        eye_steps.push_back({passes::ForwardStep::kSky, std::nullopt});
    } else if (predicated) {
        // Nothing for C to draw: the eyes draw their own sky and C and the composite are skipped.
        eye_steps.push_back({passes::ForwardStep::kSky, when(MONOPLANE_PRED_MONO_ANY, true)});
    }
    std::vector<passes::ForwardDraw> mono_steps;
    if (depth_tested) {
        mono_steps.push_back(
            {passes::ForwardStep::kChunksDiscardHidden, when(MONOPLANE_PRED_MONO_DEPTH_TESTED)});
        // No eye drew anything: no pyramid was built, nothing is hidden.
        if (predicated) {
            mono_steps.push_back(
                {passes::ForwardStep::kChunks, when(MONOPLANE_PRED_MONO_UNTESTED)});
        }
        mono_steps.push_back(
            {passes::ForwardStep::kSkyDiscardHidden, when(MONOPLANE_PRED_MONO_DEPTH_TESTED)});
        if (predicated) {
            mono_steps.push_back({passes::ForwardStep::kSky, when(MONOPLANE_PRED_MONO_UNTESTED)});
        }
    } else {
        mono_steps.push_back({passes::ForwardStep::kChunks, std::nullopt});
        mono_steps.push_back({passes::ForwardStep::kSky, when(MONOPLANE_PRED_MONO_ANY)});
    }

    // The debug view "routing" draws the same chunks, recoloured by their lists.
    if (inputs.debug == DebugView::kRouting) {
        for (auto* steps : {&eye_steps, &mono_steps}) {
            for (passes::ForwardDraw& draw : *steps) {
                if (draw.step == passes::ForwardStep::kChunks ||
                    draw.step == passes::ForwardStep::kChunksDiscardHidden) {
                    draw.step = passes::ForwardStep::kChunksShowRouting;
                }
            }
        }
    }

    double record_ms = 0.0;
    ctx_.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
        profiler_.begin_frame(cmd);
        profiler_.begin_pass(cmd, "culling");
        culling_.record_frustum_phase(cmd);
        profiler_.end_pass(cmd);
        if (shadow_needed) {
            profiler_.begin_pass(cmd, "shadow");
            shadow_.record(cmd, geometry_, shadow_draws_, glm::mat4(light_view_proj));
            profiler_.end_pass(cmd);
        }
        for (Eye eye : {Eye::kLeft, Eye::kRight}) {
            const View& view = *eyes_[static_cast<int>(eye)];
            profiler_.begin_pass(cmd, std::string(eye_name(eye)) + ".forward");
            profiler_.begin_view(cmd, eye_name(eye));
            forward_.record(cmd, view.forward_targets(), *view.forward_set, *merged_depth_set_,
                            geometry_, culling_.draws(static_cast<passes::CullView>(eye)),
                            eye_steps);
            profiler_.end_view(cmd);
            profiler_.end_pass(cmd);
        }
        if (use_mono) {
            if (depth_tested) {
                profiler_.begin_pass(cmd, "depth_pyramid");
                for (const auto& eye : eyes_) {
                    vk_core::transition(cmd, eye->depth, vk::ImageLayout::eDepthAttachmentOptimal,
                                        vk::ImageLayout::eDepthReadOnlyOptimal,
                                        Stage::eLateFragmentTests,
                                        Access::eDepthStencilAttachmentWrite, Stage::eComputeShader,
                                        Access::eShaderSampledRead);
                }
                std::array<glm::dmat3, 2> mono_to_eye;
                for (int e = 0; e < 2; ++e) mono_to_eye[e] = rig::mono_pixel_to_eye_pixel(*rig_, e);
                pyramid_.record(cmd, mono_to_eye, when(MONOPLANE_PRED_MONO_DEPTH_TESTED));
                for (const auto& eye : eyes_) {
                    vk_core::transition(cmd, eye->depth, vk::ImageLayout::eDepthReadOnlyOptimal,
                                        vk::ImageLayout::eDepthAttachmentOptimal,
                                        Stage::eComputeShader, Access::eShaderSampledRead,
                                        Stage::eEarlyFragmentTests | Stage::eLateFragmentTests,
                                        Access::eDepthStencilAttachmentRead);
                }
                profiler_.end_pass(cmd);
                if (occlusion_culled) {
                    profiler_.begin_pass(cmd, "occlusion_culling");
                    passes::with_predicate(cmd, when(MONOPLANE_PRED_MONO_DEPTH_TESTED),
                                           [&] { culling_.record_occlusion_phase(cmd); });
                    profiler_.end_pass(cmd);
                }
            }
            profiler_.begin_pass(cmd, "mono.forward");
            profiler_.begin_view(cmd, "mono");
            // Pixels hidden in both eyes stay unwritten; C's image read back shows them black.
            const bool clear_color = depth_tested && options_.read_back;
            forward_.record(cmd, mono_->forward_targets(clear_color), *mono_->forward_set,
                            *merged_depth_set_, geometry_, culling_.draws(passes::CullView::kMono),
                            mono_steps);
            profiler_.end_view(cmd);
            profiler_.end_pass(cmd);
            to_shader_read(cmd, mono_->hdr);
            to_shader_read(cmd, mono_->linear_depth);
            for (Eye eye : {Eye::kLeft, Eye::kRight}) {
                const int e = static_cast<int>(eye);
                const View& view = *eyes_[e];
                passes::CompositeParams params;
                params.mono_allocation = glm::vec2(static_cast<float>(mono_->extent.width),
                                                   static_cast<float>(mono_->extent.height));
                if (farfield) {
                    params.mapping = passes::CompositeMapping::kOffsetCopy;
                    params.pixel_offset = farfield->offsets[e];
                } else {
                    params.eye_to_mono = glm::mat4(rig_->eye_to_mono[e]);
                    // C's image is valid in [0, viewport / allocation] (Sect. 4.2). The image may
                    // be larger than the rig's own allocation: it was sized for an earlier m.
                    params.uv_scale = glm::vec2(static_cast<float>(mono_->area.width),
                                                static_cast<float>(mono_->area.height)) /
                                      params.mono_allocation;
                }
                if (inputs.debug == DebugView::kTintMono) params.tint = 1.0f;
                if (inputs.debug == DebugView::kStereoOnly) {
                    params.mapping = passes::CompositeMapping::kNothing;
                }
                params.cover_all_pixels = inputs.debug == DebugView::kMonoOnly;
                params.when = when(MONOPLANE_PRED_MONO_ANY);
                profiler_.begin_pass(cmd, std::string(eye_name(eye)) + ".composite");
                profiler_.begin_view(cmd, std::string(eye_name(eye)) + ".composite");
                composite_.record(cmd, {view.hdr, view.linear_depth, view.depth},
                                  *mono_->composite_set, params);
                profiler_.end_view(cmd);
                profiler_.end_pass(cmd);
            }
        }
        // Per-eye post-processing runs on the assembled image.
        for (Eye eye : {Eye::kLeft, Eye::kRight}) {
            const View& view = *eyes_[static_cast<int>(eye)];
            to_shader_read(cmd, view.hdr);
            profiler_.begin_pass(cmd, std::string(eye_name(eye)) + ".tonemap");
            tonemap_.record(cmd, view.display, *view.tonemap_set, options_.tonemap);
            profiler_.end_pass(cmd);
        }
        // C's own tone-mapped image exists only to be looked at (mono.png).
        if (use_mono && options_.read_back) {
            profiler_.begin_pass(cmd, "mono.tonemap");
            tonemap_.record(cmd, mono_->display, *mono_->tonemap_set, options_.tonemap);
            profiler_.end_pass(cmd);
        }
        // Read-backs after the last pass: they are not part of the frame's GPU time.
        for (const auto& view : eyes_) {
            if (options_.read_back)
                copy_to_buffer(cmd, view->display, view->extent, view->readback);
            if (options_.read_back_depth) {
                copy_to_buffer(cmd, view->linear_depth, view->extent, view->depth_readback);
            }
        }
        if (use_mono && options_.read_back) {
            copy_to_buffer(cmd, mono_->display, mono_->area, mono_->readback);
        }
        culling_.record_readback(cmd, options_.read_back_draw_lists);
        record_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpu_start)
                .count();
        if (record_after) record_after(cmd);
    });
    if (shadow_needed) shadow_light_view_proj_ = light_view_proj;
    mono_rendered_ = use_mono && options_.read_back;

    profile::FrameStats stats = profiler_.collect();
    stats.cpu_record_ms = record_ms;
    const auto counts = culling_.counts();
    for (profile::ViewStatistics& view : stats.views) {
        if (view.view == "left") view.draws = counts[MONOPLANE_COUNT_LEFT];
        if (view.view == "right") view.draws = counts[MONOPLANE_COUNT_RIGHT];
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
    if (options_.read_back_depth) {
        for (auto& eye : eyes_) {
            const auto* values = reinterpret_cast<const float*>(eye->depth_readback.mapped());
            eye->linear.assign(values,
                               values + std::size_t{eye->extent.width} * eye->extent.height);
        }
    }
    return stats;
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

}  // namespace monoplane::modes
