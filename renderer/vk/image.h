// A 2D image (optionally layered) with its memory and a view over all its layers, or one layer of
// such an image (layer_of): what single-pass stereo draws both eyes into, while every later pass
// reads and writes one eye's layer as if it were an image of its own. A transient image may
// instead be bound to memory it shares with others whose uses never overlap its own
// (graph::plan_aliasing; the render graph orders their uses).
#pragma once

#include <optional>
#include <vector>

#include "renderer/vk/context.h"
#include "renderer/vk/memory.h"

namespace monoplane::vk_core {

struct ImageDesc {
    vk::Extent2D extent;
    vk::Format format = vk::Format::eR8G8B8A8Unorm;
    vk::ImageUsageFlags usage;
    std::uint32_t layers = 1;
    vk::SampleCountFlagBits samples = vk::SampleCountFlagBits::e1;  // > 1: an MSAA target
    std::uint32_t mip_levels = 1;  // the view and transition() cover them all
    bool array_view = false;       // an array view even of one layer (for sampler2DArray)
};

// The subresources a barrier covers, and the layout the image was left in when it was made
// (initialise_image): what the render graph's executor needs of an image it synchronises.
struct ImageRange {
    vk::Image handle;
    vk::ImageAspectFlags aspect;
    std::uint32_t base_layer = 0;
    std::uint32_t layers = 1;
    std::uint32_t mip_levels = 1;
    vk::ImageLayout initial_layout = vk::ImageLayout::eUndefined;
    // The memory it shares with other images (null: memory of its own): the executor orders the
    // uses of the images bound to one memory.
    vk::DeviceMemory shared_memory{};
};

class Image {
  public:
    Image() = default;
    Image(const Context& ctx, const ImageDesc& desc);
    // Bound at offset 0 of `shared`, which must outlive it and be large enough and of a type the
    // image allows (memory_requirements).
    Image(const Context& ctx, const ImageDesc& desc, const DeviceMemory& shared);
    // What an image of `desc` needs of its memory, without making one.
    static vk::MemoryRequirements memory_requirements(const Context& ctx, const ImageDesc& desc);
    // A 2D view of one layer of `parent`, which must outlive it. Its desc() has one layer, and
    // transition() and copies address that layer only (base_layer()).
    static Image layer_of(const Context& ctx, const Image& parent, std::uint32_t layer);

    vk::Image handle() const { return handle_; }
    std::uint32_t base_layer() const { return base_layer_; }
    vk::ImageView view() const { return *view_; }
    // A view of one mip level (every layer), for a pass that writes a mip chain level by level;
    // level 0 of an image of one level is view().
    vk::ImageView mip_view(std::uint32_t mip) const;
    const ImageDesc& desc() const { return desc_; }
    vk::ImageAspectFlags aspect() const { return aspect_; }
    // Every subresource of this image (or of this layer).
    ImageRange range() const;
    // What initialise_image left it in (undefined for an image that was not initialised).
    vk::ImageLayout initial_layout() const { return initial_layout_; }
    void set_initial_layout(vk::ImageLayout layout) { initial_layout_ = layout; }

    // Whether it is bound to memory it shares with other images.
    bool shares_memory() const { return shared_memory_; }
    // The memory it is bound to (its own, or the shared one); null for a layer of another image.
    vk::DeviceMemory memory() const { return memory_handle_; }

  private:
    void make_view(const Context& ctx);

    vk::raii::Image image_{nullptr};  // null for a layer of another image
    DeviceMemory memory_{nullptr};    // null for a layer and for an image in shared memory
    vk::DeviceMemory memory_handle_{};
    bool shared_memory_ = false;
    vk::Image handle_{};
    std::uint32_t base_layer_ = 0;
    vk::raii::ImageView view_{nullptr};
    std::vector<vk::raii::ImageView> mip_views_;  // with more than one level: one per level
    ImageDesc desc_;
    vk::ImageAspectFlags aspect_;
    vk::ImageLayout initial_layout_ = vk::ImageLayout::eUndefined;
};

bool is_depth_format(vk::Format format);

// A sampler with the given filter, no mipmaps, clamped to the edge: what full-screen passes read
// their inputs with.
vk::raii::Sampler make_clamped_sampler(const Context& ctx, vk::Filter filter);
// Nearest, clamped to the edge, every mip level: what a pass reads a mip chain's texels with
// (texelFetch of the merged depth pyramid, at any level).
vk::raii::Sampler make_texel_sampler(const Context& ctx);

// Once, when an image is made and before any frame uses it: puts every subresource in `layout`,
// cleared to `clear` when given (a colour image), submitted and waited for; the image remembers the
// layout (initial_layout). The frames' own transitions are the render graph's.
void initialise_image(const Context& ctx, Image& image, vk::ImageLayout layout,
                      std::optional<vk::ClearColorValue> clear = std::nullopt);
// The same for an image the caller made by hand (a mip chain with views of its own).
void initialise_image(const Context& ctx, const ImageRange& range,
                      std::optional<vk::ClearColorValue> clear = std::nullopt);

// Uploads outside frames (scene textures): before the copies, every subresource becomes a
// transfer destination; after them, shader-readable for the fragment shaders.
void begin_upload(const vk::raii::CommandBuffer& cmd, const Image& image);
void end_upload(const vk::raii::CommandBuffer& cmd, const Image& image);

// One image layout transition with a full synchronization2 barrier between the given stages.
void transition(const vk::raii::CommandBuffer& cmd, const Image& image, vk::ImageLayout from,
                vk::ImageLayout to, vk::PipelineStageFlags2 src_stage, vk::AccessFlags2 src_access,
                vk::PipelineStageFlags2 dst_stage, vk::AccessFlags2 dst_access);

}  // namespace monoplane::vk_core
