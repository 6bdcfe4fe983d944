// A 2D image (optionally layered) with its memory and a view over all its layers.
#pragma once

#include "renderer/vk/context.h"

namespace monoplane::vk_core {

struct ImageDesc {
    vk::Extent2D extent;
    vk::Format format = vk::Format::eR8G8B8A8Unorm;
    vk::ImageUsageFlags usage;
    std::uint32_t layers = 1;
    vk::SampleCountFlagBits samples = vk::SampleCountFlagBits::e1;  // > 1: an MSAA target
};

class Image {
  public:
    Image() = default;
    Image(const Context& ctx, const ImageDesc& desc);

    vk::Image handle() const { return *image_; }
    vk::ImageView view() const { return *view_; }
    const ImageDesc& desc() const { return desc_; }
    vk::ImageAspectFlags aspect() const { return aspect_; }

  private:
    vk::raii::Image image_{nullptr};
    vk::raii::DeviceMemory memory_{nullptr};
    vk::raii::ImageView view_{nullptr};
    ImageDesc desc_;
    vk::ImageAspectFlags aspect_;
};

bool is_depth_format(vk::Format format);

// A sampler with the given filter, no mipmaps, clamped to the edge: what full-screen passes read
// their inputs with.
vk::raii::Sampler make_clamped_sampler(const Context& ctx, vk::Filter filter);

// One image layout transition with a full synchronization2 barrier between the given stages.
void transition(const vk::raii::CommandBuffer& cmd, const Image& image, vk::ImageLayout from,
                vk::ImageLayout to, vk::PipelineStageFlags2 src_stage, vk::AccessFlags2 src_access,
                vk::PipelineStageFlags2 dst_stage, vk::AccessFlags2 dst_access);

}  // namespace monoplane::vk_core
