// Image layouts come from the render graph: a use (graph::Use) stands for one layout, and this is
// the one place that says which Vulkan layout each of the graph's layouts is. A pass that names a
// layout (an attachment's, a descriptor's, a copy's) names the use its plan declares for that
// image, so the layout it records is the one the executor transitioned the image into.
//
// When may this be called: any time; pure.
#pragma once

#include "renderer/graph/resource_use.h"
#include "renderer/vk/vulkan.h"

namespace monoplane::executor {

inline vk::ImageLayout vk_layout(graph::Layout layout) {
    using graph::Layout;
    switch (layout) {
        case Layout::kUndefined:
            return vk::ImageLayout::eUndefined;
        case Layout::kGeneral:
            return vk::ImageLayout::eGeneral;
        case Layout::kColorAttachment:
            return vk::ImageLayout::eColorAttachmentOptimal;
        case Layout::kDepthAttachment:
            return vk::ImageLayout::eDepthAttachmentOptimal;
        case Layout::kDepthReadOnly:
            return vk::ImageLayout::eDepthReadOnlyOptimal;
        case Layout::kShaderReadOnly:
            return vk::ImageLayout::eShaderReadOnlyOptimal;
        case Layout::kTransferSrc:
            return vk::ImageLayout::eTransferSrcOptimal;
        case Layout::kTransferDst:
            return vk::ImageLayout::eTransferDstOptimal;
    }
    return vk::ImageLayout::eUndefined;
}

// The layout an image is in during a step that uses it so.
inline vk::ImageLayout layout_for(graph::Use use) {
    return vk_layout(graph::use_scope(use).layout);
}

}  // namespace monoplane::executor
