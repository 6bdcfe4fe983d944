#include "renderer/modes/mode_renderer.h"

#include <chrono>
#include <cmath>

#include "common/result.h"
#include "renderer/modes/farfield_rig.h"
#include "renderer/modes/frustum_culling.h"

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
    return std::nullopt;
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
    passes::DrawList draws;
    vk::raii::DescriptorSet forward_set{nullptr};
    vk::raii::DescriptorSet tonemap_set{nullptr};
    RgbaImage image;
    std::vector<float> linear;

    View(const vk_core::Context& ctx, vk::Extent2D size, std::size_t chunks)
        : extent(size),
          area(size),
          hdr(ctx, {size, passes::ForwardPass::kHdrFormat, kColorTarget}),
          depth(ctx, {size, passes::ForwardPass::kDepthFormat,
                      vk::ImageUsageFlagBits::eDepthStencilAttachment}),
          linear_depth(ctx, {size, passes::ForwardPass::kLinearDepthFormat, kColorTarget}),
          display(ctx, {size, passes::TonemapPass::kDisplayFormat, kColorTarget}),
          constants(ctx, sizeof(passes::ViewConstants), vk::BufferUsageFlagBits::eUniformBuffer,
                    vk_core::MemoryUse::kHostVisible),
          readback(ctx, vk::DeviceSize{size.width} * size.height * 4,
                   vk::BufferUsageFlagBits::eTransferDst, vk_core::MemoryUse::kHostVisible),
          depth_readback(ctx, vk::DeviceSize{size.width} * size.height * 4,
                         vk::BufferUsageFlagBits::eTransferDst, vk_core::MemoryUse::kHostVisible),
          draws(ctx, chunks) {}

    passes::ForwardTargets forward_targets(bool draw_sky) const {
        return {hdr, depth, linear_depth, area, draw_sky};
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
      profiler_(ctx) {
    const std::array pool_sizes = {
        vk::DescriptorPoolSize(vk::DescriptorType::eUniformBuffer, 3),
        vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 8),
    };
    descriptor_pool_ = vk::raii::DescriptorPool(
        ctx.device(), vk::DescriptorPoolCreateInfo(
                          vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 7, pool_sizes));
    for (auto& eye : eyes_) {
        eye = std::make_unique<View>(ctx, eye_extent, scene.chunks.size());
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
    mono_ = std::make_unique<MonoView>(ctx_, needed, scene_.chunks.size());
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
                               double blend_band, const glm::dmat4& light_view_proj) {
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
                             0.0f, 0.0f);
    view.constants.write(&c, sizeof(c));
    view.draws.assign(scene_, visible_chunks(scene_, view_proj));
}

profile::FrameStats ModeRenderer::render_frame(const FrameInputs& inputs) {
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
    }
    if (use_mono) {
        if (farfield) {
            ensure_mono_view(farfield->width, farfield->height);
            mono_->area = mono_->extent;
            update_view(*mono_, farfield->projection * rig::view_matrix(views.head, mono_in_head),
                        mono_position, inputs, mono_position, 0.0, light_view_proj);
        } else {
            ensure_mono_view(rig_->mono.allocated_width, rig_->mono.allocated_height);
            mono_->area = vk::Extent2D(static_cast<std::uint32_t>(rig_->mono.viewport_width),
                                       static_cast<std::uint32_t>(rig_->mono.viewport_height));
            update_view(*mono_, rig_->mono_projection * rig::view_matrix(views.head, mono_in_head),
                        mono_position, inputs, mono_position, 0.0, light_view_proj);
        }
    }

    double record_ms = 0.0;
    ctx_.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
        profiler_.begin_frame(cmd);
        if (shadow_needed) {
            profiler_.begin_pass(cmd, "shadow");
            shadow_.record(cmd, geometry_, shadow_draws_, glm::mat4(light_view_proj));
            profiler_.end_pass(cmd);
        }
        for (Eye eye : {Eye::kLeft, Eye::kRight}) {
            const View& view = *eyes_[static_cast<int>(eye)];
            profiler_.begin_pass(cmd, std::string(eye_name(eye)) + ".forward");
            profiler_.begin_view(cmd, eye_name(eye));
            forward_.record(cmd, view.forward_targets(!use_mono), *view.forward_set, geometry_,
                            view.draws);
            profiler_.end_view(cmd);
            profiler_.end_pass(cmd);
        }
        if (use_mono) {
            profiler_.begin_pass(cmd, "mono.forward");
            profiler_.begin_view(cmd, "mono");
            forward_.record(cmd, mono_->forward_targets(true), *mono_->forward_set, geometry_,
                            mono_->draws);
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
                    params.uv_scale =
                        glm::vec2(static_cast<float>(mono_->area.width) / mono_->extent.width,
                                  static_cast<float>(mono_->area.height) / mono_->extent.height);
                }
                if (inputs.debug == DebugView::kTintMono) params.tint = 1.0f;
                if (inputs.debug == DebugView::kStereoOnly) {
                    params.mapping = passes::CompositeMapping::kNothing;
                }
                params.cover_all_pixels = inputs.debug == DebugView::kMonoOnly;
                profiler_.begin_pass(cmd, std::string(eye_name(eye)) + ".composite");
                composite_.record(cmd, {view.hdr, view.linear_depth, view.depth},
                                  *mono_->composite_set, params);
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
            if (options_.read_back) copy_to_buffer(cmd, view.display, view.extent, view.readback);
            if (options_.read_back_depth) {
                copy_to_buffer(cmd, view.linear_depth, view.extent, view.depth_readback);
            }
        }
        if (use_mono) {
            profiler_.begin_pass(cmd, "mono.tonemap");
            tonemap_.record(cmd, mono_->display, *mono_->tonemap_set, options_.tonemap);
            profiler_.end_pass(cmd);
            if (options_.read_back)
                copy_to_buffer(cmd, mono_->display, mono_->area, mono_->readback);
        }
        record_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpu_start)
                .count();
    });
    if (shadow_needed) shadow_light_view_proj_ = light_view_proj;
    mono_rendered_ = use_mono;

    profile::FrameStats stats = profiler_.collect();
    stats.cpu_record_ms = record_ms;
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
