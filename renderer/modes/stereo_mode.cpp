#include "renderer/modes/stereo_mode.h"

#include <chrono>
#include <cmath>

#include "renderer/modes/frustum_culling.h"

namespace monoplane::modes {
namespace {

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

passes::ViewConstants view_constants(const glm::dmat4& view_proj, const glm::dvec3& eye_position,
                                     const glm::dmat4& light_view_proj,
                                     const scenes::Lighting& lighting, float shadow_texel) {
    passes::ViewConstants c{};
    c.view_proj = glm::mat4(view_proj);
    c.inv_view_proj = glm::mat4(glm::inverse(view_proj));
    c.light_view_proj = glm::mat4(light_view_proj);
    c.camera_position = glm::vec4(glm::vec3(eye_position), 1.0f);
    c.sun_direction = glm::vec4(glm::normalize(lighting.sun_direction), 0.0f);
    c.sun_radiance = glm::vec4(lighting.sun_radiance, 0.0f);
    c.sky_zenith = glm::vec4(lighting.sky_zenith, 0.0f);
    c.sky_horizon = glm::vec4(lighting.sky_horizon, 0.0f);
    c.ground_albedo = glm::vec4(lighting.ground_albedo, 0.0f);
    c.shadow_params = glm::vec4(shadow_texel, 0.0f, 0.0f, 0.0f);
    return c;
}

}  // namespace

struct StereoMode::EyeView {
    vk_core::Image hdr;
    vk_core::Image depth;
    vk_core::Image display;
    vk_core::Buffer constants;
    vk_core::Buffer readback;
    passes::DrawList draws;
    vk::raii::DescriptorSet forward_set{nullptr};
    vk::raii::DescriptorSet tonemap_set{nullptr};
    RgbaImage image;

    EyeView(const vk_core::Context& ctx, vk::Extent2D extent, std::size_t chunks)
        : hdr(ctx, {extent, passes::ForwardPass::kHdrFormat,
                    vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eSampled}),
          depth(ctx, {extent, passes::ForwardPass::kDepthFormat,
                      vk::ImageUsageFlagBits::eDepthStencilAttachment |
                          vk::ImageUsageFlagBits::eSampled}),
          display(ctx, {extent, passes::TonemapPass::kDisplayFormat,
                        vk::ImageUsageFlagBits::eColorAttachment |
                            vk::ImageUsageFlagBits::eTransferSrc}),
          constants(ctx, sizeof(passes::ViewConstants), vk::BufferUsageFlagBits::eUniformBuffer,
                    vk_core::MemoryUse::kHostVisible),
          readback(ctx, vk::DeviceSize{extent.width} * extent.height * 4,
                   vk::BufferUsageFlagBits::eTransferDst, vk_core::MemoryUse::kHostVisible),
          draws(ctx, chunks) {}
};

StereoMode::StereoMode(const vk_core::Context& ctx, const scenes::Scene& scene,
                       vk::Extent2D eye_extent, const RendererOptions& options)
    : ctx_(ctx),
      scene_(scene),
      options_(options),
      geometry_(ctx, scene),
      shadow_(ctx, options.shadow),
      forward_(ctx),
      tonemap_(ctx),
      shadow_draws_(ctx, scene.chunks.size()),
      profiler_(ctx) {
    const std::array pool_sizes = {
        vk::DescriptorPoolSize(vk::DescriptorType::eUniformBuffer, 2),
        vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 4),
    };
    descriptor_pool_ = vk::raii::DescriptorPool(
        ctx.device(), vk::DescriptorPoolCreateInfo(
                          vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 4, pool_sizes));
    for (auto& eye : eyes_) {
        eye = std::make_unique<EyeView>(ctx, eye_extent, scene.chunks.size());
        const std::array layouts = {forward_.set_layout(), tonemap_.set_layout()};
        vk::raii::DescriptorSets sets(ctx.device(),
                                      vk::DescriptorSetAllocateInfo(*descriptor_pool_, layouts));
        eye->forward_set = std::move(sets[0]);
        eye->tonemap_set = std::move(sets[1]);
        const vk::DescriptorBufferInfo constants_info(eye->constants.handle(), 0, VK_WHOLE_SIZE);
        const vk::DescriptorImageInfo shadow_info(shadow_.sampler(), shadow_.view(),
                                                  vk::ImageLayout::eShaderReadOnlyOptimal);
        const vk::DescriptorImageInfo hdr_info(tonemap_.sampler(), eye->hdr.view(),
                                               vk::ImageLayout::eShaderReadOnlyOptimal);
        const std::array writes = {
            vk::WriteDescriptorSet(*eye->forward_set, 0, 0, vk::DescriptorType::eUniformBuffer, {},
                                   constants_info),
            vk::WriteDescriptorSet(*eye->forward_set, 1, 0,
                                   vk::DescriptorType::eCombinedImageSampler, shadow_info),
            vk::WriteDescriptorSet(*eye->tonemap_set, 0, 0,
                                   vk::DescriptorType::eCombinedImageSampler, hdr_info),
        };
        ctx.device().updateDescriptorSets(writes, {});
    }
    std::vector<std::uint32_t> all(scene.chunks.size());
    for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    shadow_draws_.assign(scene, all);
}

StereoMode::~StereoMode() = default;

profile::FrameStats StereoMode::render_frame(const StereoViewInputs& inputs) {
    using Stage = vk::PipelineStageFlagBits2;
    using Access = vk::AccessFlagBits2;
    const auto cpu_start = std::chrono::steady_clock::now();

    const scenes::Aabb region =
        shadow_region(scene_, inputs.head.position, options_.shadow.region_radius_m);
    const glm::dmat4 light_view_proj =
        passes::fit_light_view_proj(glm::dvec3(scene_.lighting.sun_direction), region);
    const bool shadow_needed = shadow_light_view_proj_ != light_view_proj;

    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        EyeView& view = *eyes_[static_cast<int>(eye)];
        const glm::dmat4 view_proj = eye_view_proj(inputs, eye);
        const glm::dvec3 position =
            glm::dvec3(rig::to_matrix(inputs.head) * glm::dvec4(eye_offset(eye, inputs.ipd), 1.0));
        const passes::ViewConstants constants = view_constants(
            view_proj, position, light_view_proj, scene_.lighting, shadow_.texel_size());
        view.constants.write(&constants, sizeof(constants));
        view.draws.assign(scene_, visible_chunks(scene_, view_proj));
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
            EyeView& view = *eyes_[static_cast<int>(eye)];
            profiler_.begin_pass(cmd, std::string(eye_name(eye)) + ".forward");
            profiler_.begin_view(cmd, eye_name(eye));
            forward_.record(cmd, {view.hdr, view.depth}, *view.forward_set, geometry_, view.draws);
            profiler_.end_view(cmd);
            profiler_.end_pass(cmd);
        }
        for (Eye eye : {Eye::kLeft, Eye::kRight}) {
            EyeView& view = *eyes_[static_cast<int>(eye)];
            vk_core::transition(cmd, view.hdr, vk::ImageLayout::eColorAttachmentOptimal,
                                vk::ImageLayout::eShaderReadOnlyOptimal,
                                Stage::eColorAttachmentOutput, Access::eColorAttachmentWrite,
                                Stage::eFragmentShader, Access::eShaderSampledRead);
            profiler_.begin_pass(cmd, std::string(eye_name(eye)) + ".tonemap");
            tonemap_.record(cmd, view.display, *view.tonemap_set, options_.tonemap);
            profiler_.end_pass(cmd);
            if (options_.read_back) {
                vk_core::transition(cmd, view.display, vk::ImageLayout::eColorAttachmentOptimal,
                                    vk::ImageLayout::eTransferSrcOptimal,
                                    Stage::eColorAttachmentOutput, Access::eColorAttachmentWrite,
                                    Stage::eTransfer, Access::eTransferRead);
                const vk::Extent2D extent = view.display.desc().extent;
                cmd.copyImageToBuffer(
                    view.display.handle(), vk::ImageLayout::eTransferSrcOptimal,
                    view.readback.handle(),
                    vk::BufferImageCopy(
                        0, 0, 0,
                        vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, 0, 1),
                        {0, 0, 0}, vk::Extent3D(extent, 1)));
            }
        }
        record_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpu_start)
                .count();
    });
    if (shadow_needed) shadow_light_view_proj_ = light_view_proj;

    profile::FrameStats stats = profiler_.collect();
    stats.cpu_record_ms = record_ms;
    if (options_.read_back) {
        for (auto& eye : eyes_) {
            const vk::Extent2D extent = eye->display.desc().extent;
            eye->image.width = extent.width;
            eye->image.height = extent.height;
            const auto* bytes = reinterpret_cast<const std::uint8_t*>(eye->readback.mapped());
            eye->image.pixels.assign(bytes, bytes + eye->readback.size());
        }
    }
    return stats;
}

const RgbaImage& StereoMode::eye_image(Eye eye) const {
    return eyes_[static_cast<int>(eye)]->image;
}

}  // namespace monoplane::modes
