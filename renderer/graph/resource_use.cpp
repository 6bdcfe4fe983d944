#include "renderer/graph/resource_use.h"

namespace monoplane::graph {

UseScope use_scope(Use use) {
    constexpr Stage kDepthTests = Stage::kEarlyFragmentTests | Stage::kLateFragmentTests;
    constexpr Stage kShaders = Stage::kFragmentShader | Stage::kComputeShader;
    switch (use) {
        case Use::kColorWrite:
            return {Stage::kColorAttachmentOutput, Access::kColorAttachmentWrite,
                    Layout::kColorAttachment, true};
        case Use::kColorBlend:
            return {Stage::kColorAttachmentOutput,
                    Access::kColorAttachmentRead | Access::kColorAttachmentWrite,
                    Layout::kColorAttachment, true};
        case Use::kDepthWrite:
            return {kDepthTests,
                    Access::kDepthStencilAttachmentRead | Access::kDepthStencilAttachmentWrite,
                    Layout::kDepthAttachment, true};
        case Use::kDepthTest:
            return {kDepthTests, Access::kDepthStencilAttachmentRead, Layout::kDepthAttachment,
                    false};
        case Use::kDepthSampledCompute:
            return {Stage::kComputeShader, Access::kShaderSampledRead, Layout::kDepthReadOnly,
                    false};
        case Use::kSampledFragment:
            return {Stage::kFragmentShader, Access::kShaderSampledRead, Layout::kShaderReadOnly,
                    false};
        case Use::kSampledCompute:
            return {Stage::kComputeShader, Access::kShaderSampledRead, Layout::kShaderReadOnly,
                    false};
        case Use::kSampledAny:
            return {kShaders, Access::kShaderSampledRead, Layout::kShaderReadOnly, false};
        case Use::kGeneralSampled:
            return {kShaders, Access::kShaderSampledRead, Layout::kGeneral, false};
        case Use::kStorageRead:
            return {Stage::kComputeShader, Access::kShaderStorageRead, Layout::kGeneral, false};
        case Use::kStorageWrite:
            return {Stage::kComputeShader, Access::kShaderStorageRead | Access::kShaderStorageWrite,
                    Layout::kGeneral, true};
        case Use::kTransferSrc:
            return {Stage::kTransfer, Access::kTransferRead, Layout::kTransferSrc, false};
        case Use::kTransferDst:
            return {Stage::kTransfer, Access::kTransferWrite, Layout::kTransferDst, true};
        case Use::kIndirectArgs:
            // The draws' shaders read the lists too (the instance's chunk; the routing view's
            // colours in the fragment shader).
            return {Stage::kDrawIndirect | Stage::kVertexShader | Stage::kFragmentShader,
                    Access::kIndirectCommandRead | Access::kShaderStorageRead, Layout::kUndefined,
                    false};
        case Use::kConditional:
            return {Stage::kConditionalRendering, Access::kConditionalRenderingRead,
                    Layout::kUndefined, false};
        case Use::kHostRead:
            return {Stage::kHost, Access::kHostRead, Layout::kUndefined, false};
    }
    return {};
}

std::string use_name(Use use) {
    switch (use) {
        case Use::kColorWrite:
            return "color-write";
        case Use::kColorBlend:
            return "color-blend";
        case Use::kDepthWrite:
            return "depth-write";
        case Use::kDepthTest:
            return "depth-test";
        case Use::kDepthSampledCompute:
            return "depth-sampled-compute";
        case Use::kSampledFragment:
            return "sampled-fragment";
        case Use::kSampledCompute:
            return "sampled-compute";
        case Use::kSampledAny:
            return "sampled-any";
        case Use::kGeneralSampled:
            return "general-sampled";
        case Use::kStorageRead:
            return "storage-read";
        case Use::kStorageWrite:
            return "storage-write";
        case Use::kTransferSrc:
            return "transfer-src";
        case Use::kTransferDst:
            return "transfer-dst";
        case Use::kIndirectArgs:
            return "indirect-args";
        case Use::kConditional:
            return "conditional";
        case Use::kHostRead:
            return "host-read";
    }
    return "?";
}

}  // namespace monoplane::graph
