#include "renderer/vk/image.h"

#include "common/programming_error.h"
#include "renderer/vk/memory.h"

namespace monoplane::vk_core {

bool is_depth_format(vk::Format format) {
    return format == vk::Format::eD32Sfloat || format == vk::Format::eD16Unorm ||
           format == vk::Format::eD24UnormS8Uint || format == vk::Format::eD32SfloatS8Uint;
}

namespace {

vk::ImageCreateInfo create_info(const ImageDesc& desc) {
    return vk::ImageCreateInfo({}, vk::ImageType::e2D, desc.format, vk::Extent3D(desc.extent, 1),
                               desc.mip_levels, desc.layers, desc.samples,
                               vk::ImageTiling::eOptimal, desc.usage, vk::SharingMode::eExclusive);
}

vk::ImageAspectFlags aspect_of(vk::Format format) {
    return is_depth_format(format) ? vk::ImageAspectFlagBits::eDepth
                                   : vk::ImageAspectFlagBits::eColor;
}

}  // namespace

Image::Image(const Context& ctx, const ImageDesc& desc)
    : image_(ctx.device(), create_info(desc)), desc_(desc), aspect_(aspect_of(desc.format)) {
    memory_ = allocate_memory(ctx, image_.getMemoryRequirements(),
                              vk::MemoryPropertyFlagBits::eDeviceLocal);
    image_.bindMemory(*memory_, 0);
    memory_handle_ = *memory_;
    make_view(ctx);
}

Image::Image(const Context& ctx, const ImageDesc& desc, const DeviceMemory& shared)
    : image_(ctx.device(), create_info(desc)),
      memory_handle_(*shared),
      shared_memory_(true),
      desc_(desc),
      aspect_(aspect_of(desc.format)) {
    MONOPLANE_EXPECTS(image_.getMemoryRequirements().size <= shared.bytes());
    image_.bindMemory(*shared, 0);
    make_view(ctx);
}

vk::MemoryRequirements Image::memory_requirements(const Context& ctx, const ImageDesc& desc) {
    const vk::ImageCreateInfo info = create_info(desc);
    return ctx.device()
        .getImageMemoryRequirements(vk::DeviceImageMemoryRequirements(&info))
        .memoryRequirements;
}

void Image::make_view(const Context& ctx) {
    handle_ = *image_;
    const auto view_type =
        desc_.layers > 1 || desc_.array_view ? vk::ImageViewType::e2DArray : vk::ImageViewType::e2D;
    view_ = vk::raii::ImageView(
        ctx.device(), vk::ImageViewCreateInfo({}, *image_, view_type, desc_.format, {},
                                              vk::ImageSubresourceRange(
                                                  aspect_, 0, desc_.mip_levels, 0, desc_.layers)));
    if (desc_.mip_levels == 1) return;
    for (std::uint32_t mip = 0; mip < desc_.mip_levels; ++mip) {
        mip_views_.emplace_back(
            ctx.device(),
            vk::ImageViewCreateInfo({}, *image_, view_type, desc_.format, {},
                                    vk::ImageSubresourceRange(aspect_, mip, 1, 0, desc_.layers)));
    }
}

vk::ImageView Image::mip_view(std::uint32_t mip) const {
    if (desc_.mip_levels == 1 && mip == 0) return *view_;
    return *mip_views_.at(mip);
}

Image Image::layer_of(const Context& ctx, const Image& parent, std::uint32_t layer) {
    Image image;
    image.desc_ = parent.desc_;
    image.desc_.layers = 1;
    image.aspect_ = parent.aspect_;
    image.handle_ = parent.handle_;
    image.base_layer_ = parent.base_layer_ + layer;
    image.view_ = vk::raii::ImageView(
        ctx.device(),
        vk::ImageViewCreateInfo({}, parent.handle_, vk::ImageViewType::e2D, parent.desc_.format, {},
                                vk::ImageSubresourceRange(image.aspect_, 0, parent.desc_.mip_levels,
                                                          image.base_layer_, 1)));
    return image;
}

vk::raii::Sampler make_clamped_sampler(const Context& ctx, vk::Filter filter) {
    return vk::raii::Sampler(
        ctx.device(), vk::SamplerCreateInfo({}, filter, filter, vk::SamplerMipmapMode::eNearest,
                                            vk::SamplerAddressMode::eClampToEdge,
                                            vk::SamplerAddressMode::eClampToEdge,
                                            vk::SamplerAddressMode::eClampToEdge));
}

vk::raii::Sampler make_texel_sampler(const Context& ctx) {
    return vk::raii::Sampler(
        ctx.device(),
        vk::SamplerCreateInfo({}, vk::Filter::eNearest, vk::Filter::eNearest,
                              vk::SamplerMipmapMode::eNearest, vk::SamplerAddressMode::eClampToEdge,
                              vk::SamplerAddressMode::eClampToEdge,
                              vk::SamplerAddressMode::eClampToEdge, 0.0f, VK_FALSE, 1.0f, VK_FALSE,
                              vk::CompareOp::eNever, 0.0f, VK_LOD_CLAMP_NONE));
}

ImageRange Image::range() const {
    return {handle_,
            aspect_,
            base_layer_,
            desc_.layers,
            desc_.mip_levels,
            initial_layout_,
            shared_memory_ ? memory_handle_ : vk::DeviceMemory{}};
}

void initialise_image(const Context& ctx, const ImageRange& range,
                      std::optional<vk::ClearColorValue> clear) {
    using Stage = vk::PipelineStageFlagBits2;
    using Access = vk::AccessFlagBits2;
    const vk::ImageSubresourceRange all(range.aspect, 0, range.mip_levels, range.base_layer,
                                        range.layers);
    ctx.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
        const vk::ImageLayout first =
            clear ? vk::ImageLayout::eTransferDstOptimal : range.initial_layout;
        const vk::ImageMemoryBarrier2 to_first(Stage::eNone, Access::eNone, Stage::eAllTransfer,
                                               Access::eTransferWrite, vk::ImageLayout::eUndefined,
                                               first, VK_QUEUE_FAMILY_IGNORED,
                                               VK_QUEUE_FAMILY_IGNORED, range.handle, all);
        cmd.pipelineBarrier2(vk::DependencyInfo({}, {}, {}, to_first));
        if (!clear) return;
        cmd.clearColorImage(range.handle, first, *clear, all);
        // The submission's wait makes the clear available to every later use.
        const vk::ImageMemoryBarrier2 to_layout(
            Stage::eAllTransfer, Access::eTransferWrite, Stage::eAllCommands,
            Access::eMemoryRead | Access::eMemoryWrite, first, range.initial_layout,
            VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, range.handle, all);
        cmd.pipelineBarrier2(vk::DependencyInfo({}, {}, {}, to_layout));
    });
}

void initialise_image(const Context& ctx, Image& image, vk::ImageLayout layout,
                      std::optional<vk::ClearColorValue> clear) {
    image.set_initial_layout(layout);
    initialise_image(ctx, image.range(), clear);
}

void begin_upload(const vk::raii::CommandBuffer& cmd, const Image& image) {
    using Stage = vk::PipelineStageFlagBits2;
    using Access = vk::AccessFlagBits2;
    transition(cmd, image, vk::ImageLayout::eUndefined, vk::ImageLayout::eTransferDstOptimal,
               Stage::eNone, Access::eNone, Stage::eAllTransfer, Access::eTransferWrite);
}

void end_upload(const vk::raii::CommandBuffer& cmd, const Image& image) {
    using Stage = vk::PipelineStageFlagBits2;
    using Access = vk::AccessFlagBits2;
    transition(cmd, image, vk::ImageLayout::eTransferDstOptimal,
               vk::ImageLayout::eShaderReadOnlyOptimal, Stage::eAllTransfer, Access::eTransferWrite,
               Stage::eFragmentShader, Access::eShaderSampledRead);
}

void transition(const vk::raii::CommandBuffer& cmd, const Image& image, vk::ImageLayout from,
                vk::ImageLayout to, vk::PipelineStageFlags2 src_stage, vk::AccessFlags2 src_access,
                vk::PipelineStageFlags2 dst_stage, vk::AccessFlags2 dst_access) {
    const vk::ImageMemoryBarrier2 barrier(
        src_stage, src_access, dst_stage, dst_access, from, to, VK_QUEUE_FAMILY_IGNORED,
        VK_QUEUE_FAMILY_IGNORED, image.handle(),
        vk::ImageSubresourceRange(image.aspect(), 0, image.desc().mip_levels, image.base_layer(),
                                  image.desc().layers));
    cmd.pipelineBarrier2(vk::DependencyInfo({}, {}, {}, barrier));
}

}  // namespace monoplane::vk_core
