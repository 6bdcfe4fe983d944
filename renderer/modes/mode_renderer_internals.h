// ModeRenderer's private parts, shared by its source files (mode_renderer.cpp: views and frame
// preparation; frame_recording.cpp: one recorder per kind of planned pass; frame_results.cpp: a
// completed frame's statistics and read-backs; resource_bindings.cpp: the plan's resources on the
// device): the views' images and outputs and one frame's state. Include nowhere else.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/programming_error.h"
#include "renderer/modes/farfield_rig.h"
#include "renderer/modes/mode_renderer.h"
#include "renderer/modes/transient_memory.h"
#include "renderer/passes/shared/display_format.h"

namespace monoplane::modes {

constexpr vk::ImageUsageFlags kColorTarget = vk::ImageUsageFlagBits::eColorAttachment |
                                             vk::ImageUsageFlagBits::eSampled |
                                             vk::ImageUsageFlagBits::eTransferSrc;

// What a view's targets must support beyond the basic forward pass.
struct ViewFeatures {
    bool velocity = false;  // TAA: velocity, and (eyes) two history images
    bool history = false;
    vk::SampleCountFlagBits samples = vk::SampleCountFlagBits::e1;
};

// The images a forward pass writes: one camera's, or both eyes' as two-layer images (single-pass
// stereo), or one layer of those.
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

    // The image of a forward role (hdr, depth, linear depth, velocity, the samples); null for
    // another role, or one these images lack.
    const vk_core::Image* forward_image(plan::ImageRole role) const {
        const auto optional = [](const std::optional<vk_core::Image>& image) {
            return image ? &*image : nullptr;
        };
        switch (role) {
            case plan::ImageRole::kHdr:
                return &hdr;
            case plan::ImageRole::kDepth:
                return &depth;
            case plan::ImageRole::kLinearDepth:
                return &linear_depth;
            case plan::ImageRole::kVelocity:
                return optional(velocity);
            case plan::ImageRole::kHdrSamples:
                return optional(hdr_samples);
            case plan::ImageRole::kLinearDepthSamples:
                return optional(linear_depth_samples);
            case plan::ImageRole::kDepthSamples:
                return optional(depth_samples);
            default:
                return nullptr;
        }
    }

    // The images of one camera's forward targets with their descriptions, by role: what the
    // constructor makes, and what may share memory (TransientMemory).
    static std::vector<TransientImage> images(plan::ViewId view, vk::Extent2D size,
                                              const ViewFeatures& features, std::uint32_t layers) {
        using plan::ImageRole;
        const auto image = [&](ImageRole role, vk::Format format, vk::ImageUsageFlags usage,
                               vk::SampleCountFlagBits samples = vk::SampleCountFlagBits::e1) {
            return TransientImage{{view, false, role, plan::BufferRole::kDrawLists},
                                  vk_core::ImageDesc{size, format, usage, layers, samples}};
        };
        std::vector<TransientImage> images = {
            image(ImageRole::kHdr, passes::ForwardPass::kHdrFormat, kColorTarget),
            // Sampled: the merged depth pyramid reads the eyes' depth.
            image(
                ImageRole::kDepth, passes::ForwardPass::kDepthFormat,
                vk::ImageUsageFlagBits::eDepthStencilAttachment | vk::ImageUsageFlagBits::eSampled),
            image(ImageRole::kLinearDepth, passes::ForwardPass::kLinearDepthFormat, kColorTarget)};
        if (features.velocity) {
            images.push_back(
                image(ImageRole::kVelocity, passes::ForwardPass::kVelocityFormat,
                      vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eSampled));
        }
        if (features.samples != vk::SampleCountFlagBits::e1) {
            // Transient: only their resolve is kept.
            const vk::ImageUsageFlags usage = vk::ImageUsageFlagBits::eColorAttachment |
                                              vk::ImageUsageFlagBits::eTransientAttachment;
            images.push_back(image(ImageRole::kHdrSamples, passes::ForwardPass::kHdrFormat, usage,
                                   features.samples));
            images.push_back(image(ImageRole::kLinearDepthSamples,
                                   passes::ForwardPass::kLinearDepthFormat, usage,
                                   features.samples));
            images.push_back(image(ImageRole::kDepthSamples, passes::ForwardPass::kDepthFormat,
                                   vk::ImageUsageFlagBits::eDepthStencilAttachment |
                                       vk::ImageUsageFlagBits::eTransientAttachment,
                                   features.samples));
        }
        return images;
    }

    // `memory` places some of them in memory they share (nullptr: each its own); `view` is the
    // camera whose images they are.
    ForwardImages(const vk_core::Context& ctx, vk::Extent2D size, const ViewFeatures& features,
                  std::uint32_t layers, const TransientMemory* memory = nullptr,
                  plan::ViewId view = plan::ViewId::kNone)
        : ForwardImages(ctx, images(view, size, features, layers), memory) {}

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

  private:
    ForwardImages(const vk_core::Context& ctx, const std::vector<TransientImage>& images,
                  const TransientMemory* memory)
        : hdr(make(ctx, images, memory, plan::ImageRole::kHdr)),
          depth(make(ctx, images, memory, plan::ImageRole::kDepth)),
          linear_depth(make(ctx, images, memory, plan::ImageRole::kLinearDepth)) {
        for (const TransientImage& image : images) {
            std::optional<vk_core::Image>* optional = nullptr;
            switch (image.key.image) {
                case plan::ImageRole::kVelocity:
                    optional = &velocity;
                    break;
                case plan::ImageRole::kHdrSamples:
                    optional = &hdr_samples;
                    break;
                case plan::ImageRole::kLinearDepthSamples:
                    optional = &linear_depth_samples;
                    break;
                case plan::ImageRole::kDepthSamples:
                    optional = &depth_samples;
                    break;
                default:
                    continue;
            }
            optional->emplace(make(ctx, images, memory, image.key.image));
        }
    }

    static vk_core::Image make(const vk_core::Context& ctx,
                               const std::vector<TransientImage>& images,
                               const TransientMemory* memory, plan::ImageRole role) {
        for (const TransientImage& image : images) {
            if (image.key.image == role) {
                return make_view_image(ctx, memory, image.key.view, role, image.desc);
            }
        }
        programming_error("ForwardImages: no " + plan::image_role_name(role));
    }
};

// What a camera owns beyond its forward images: its tone-mapped image, its constants, its
// read-back buffers and, under TAA, its two history images (this frame's output and the last).
struct ViewOutputs {
    vk_core::Image display;
    vk_core::Buffer constants;
    vk_core::Buffer readback;
    vk_core::Buffer depth_readback;
    std::array<std::optional<vk_core::Image>, 2> history;

    static vk_core::ImageDesc display_desc(vk::Extent2D size) {
        return {size, passes::kDisplayFormat, kColorTarget};
    }

    ViewOutputs(const vk_core::Context& ctx, vk::Extent2D size, const ViewFeatures& features,
                const TransientMemory* memory = nullptr, plan::ViewId view = plan::ViewId::kNone)
        : display(
              make_view_image(ctx, memory, view, plan::ImageRole::kDisplay, display_desc(size))),
          // Filled through the frame's uploads (vk_core::FrameUploads), not a mapping.
          constants(ctx, sizeof(passes::ViewConstants), vk::BufferUsageFlagBits::eUniformBuffer,
                    vk_core::MemoryUse::kDeviceLocal),
          readback(ctx, vk::DeviceSize{size.width} * size.height * 4,
                   vk::BufferUsageFlagBits::eTransferDst, vk_core::MemoryUse::kHostVisible),
          depth_readback(ctx, vk::DeviceSize{size.width} * size.height * 4,
                         vk::BufferUsageFlagBits::eTransferDst, vk_core::MemoryUse::kHostVisible) {
        if (!features.history) return;
        for (auto& image : history) {
            // The TAA unit's resolve: HDR colour, in the HDR images' format.
            image.emplace(ctx, vk_core::ImageDesc{size, passes::ForwardPass::kHdrFormat,
                                                  vk::ImageUsageFlagBits::eColorAttachment |
                                                      vk::ImageUsageFlagBits::eSampled});
        }
    }
};

// The targets and per-frame data of one camera. With single-pass stereo the eyes' forward images
// are the layers of one set of two-layer images (ModeRenderer::eye_layers_).
struct ModeRenderer::View : ForwardImages, ViewOutputs {
    vk::Extent2D extent;                        // the images' size (C: its allocation)
    vk::Extent2D area;                          // the region drawn (C: its viewport, eq. 8)
    passes::ViewConstants written_constants{};  // what this frame's constants hold
    RgbaImage image;
    std::vector<float> linear;
    glm::dmat4 previous_unjittered{1.0};  // last frame's world -> clip without jitter
    bool has_previous = false;
    std::unique_ptr<passes::SsaoImages> ssao;  // with SSAO
    std::vector<float> ao;
    EyeFrameGeometry geometry;

    // A camera with forward images of its own (C, and the eyes of two-pass stereo). `memory`
    // places some of its images in memory they share with others (TransientMemory).
    View(const vk_core::Context& ctx, vk::Extent2D size, const ViewFeatures& features,
         const TransientMemory* memory = nullptr, plan::ViewId view = plan::ViewId::kNone)
        : ForwardImages(ctx, size, features, 1, memory, view),
          ViewOutputs(ctx, size, features, memory, view),
          extent(size),
          area(size) {}

    // An eye: layer `layer` of both eyes' forward images.
    View(const vk_core::Context& ctx, const ForwardImages& both, std::uint32_t layer,
         const ViewFeatures& features)
        : ForwardImages(ctx, both, layer),
          ViewOutputs(ctx, both.hdr.desc().extent, features),
          extent(both.hdr.desc().extent),
          area(extent) {}

    // The eyes' images of two-pass stereo that may share memory (single-pass stereo's two-layer
    // images share none), placed over `plans`: every plan the renderer may run.
    static std::unique_ptr<TransientMemory> eye_memory(const vk_core::Context& ctx,
                                                       vk::Extent2D size,
                                                       const ViewFeatures& features,
                                                       const std::vector<plan::FramePlan>& plans) {
        std::vector<TransientImage> images;
        for (int eye = 0; eye < 2; ++eye) {
            for (TransientImage& image :
                 ForwardImages::images(plan::eye_view(eye), size, features, 1)) {
                images.push_back(std::move(image));
            }
        }
        return std::make_unique<TransientMemory>(ctx, images, plans);
    }
};

// C's images that share memory, made before them (MonoView's first base).
struct MonoMemory {
    TransientMemory memory;
};

// C: its images that may share memory are its depth and its display image (its colour, linear
// depth and velocity are sampled by the composite near the edge of its viewport, beyond which no
// pass writes them: texels there must stay as they are). `plans`: every plan the renderer may run.
struct ModeRenderer::MonoView : MonoMemory, View {
    MonoView(const vk_core::Context& ctx, vk::Extent2D size, const ViewFeatures& features,
             const std::vector<plan::FramePlan>& plans = {})
        : MonoMemory{plans.empty() ? TransientMemory()
                                   : TransientMemory(ctx, transient_images(size, features), plans)},
          View(ctx, size, features, &memory, plan::ViewId::kMono) {}

    static std::vector<TransientImage> transient_images(vk::Extent2D size,
                                                        const ViewFeatures& features) {
        std::vector<TransientImage> images;
        for (TransientImage& image : images_of(size, features)) {
            if (image.key.image == plan::ImageRole::kDepth) images.push_back(std::move(image));
        }
        images.push_back(
            {{plan::ViewId::kMono, false, plan::ImageRole::kDisplay, plan::BufferRole::kDrawLists},
             display_desc(size)});
        return images;
    }

  private:
    static std::vector<TransientImage> images_of(vk::Extent2D size, const ViewFeatures& features) {
        return ForwardImages::images(plan::ViewId::kMono, size, features, 1);
    }
};

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
    plan::MonoCulling mono_culling = plan::MonoCulling::kNoOpt;
    bool measuring_variant = false;  // this frame's time goes to the chooser
    std::uint32_t slot = 0;          // the frame-in-flight slot it is recorded into
    // What every unit's recording reads of the frame beyond its resources, worked out once the
    // frame's plan, views and slot are known (unit_frame_values).
    passes::UnitFrameValues unit_values;
};

}  // namespace monoplane::modes
