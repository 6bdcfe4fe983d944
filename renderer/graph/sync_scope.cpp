#include "renderer/graph/sync_scope.h"

#include <array>
#include <utility>

namespace monoplane::graph {
namespace {

template <class Bits, std::size_t N>
std::string bit_names(Bits mask, const std::array<std::pair<Bits, const char*>, N>& table) {
    if (!any(mask)) return "none";
    std::string names;
    for (const auto& [bit, name] : table) {
        if (!covers(mask, bit)) continue;
        if (!names.empty()) names += "|";
        names += name;
    }
    return names;
}

constexpr std::array<std::pair<Stage, const char*>, 11> kStageNames = {{
    {Stage::kDrawIndirect, "draw-indirect"},
    {Stage::kVertexShader, "vertex-shader"},
    {Stage::kGeometryShader, "geometry-shader"},
    {Stage::kEarlyFragmentTests, "early-fragment-tests"},
    {Stage::kFragmentShader, "fragment-shader"},
    {Stage::kLateFragmentTests, "late-fragment-tests"},
    {Stage::kColorAttachmentOutput, "color-attachment-output"},
    {Stage::kComputeShader, "compute-shader"},
    {Stage::kTransfer, "transfer"},
    {Stage::kConditionalRendering, "conditional-rendering"},
    {Stage::kHost, "host"},
}};

constexpr std::array<std::pair<Access, const char*>, 13> kAccessNames = {{
    {Access::kIndirectCommandRead, "indirect-command-read"},
    {Access::kUniformRead, "uniform-read"},
    {Access::kShaderSampledRead, "shader-sampled-read"},
    {Access::kShaderStorageRead, "shader-storage-read"},
    {Access::kShaderStorageWrite, "shader-storage-write"},
    {Access::kColorAttachmentRead, "color-attachment-read"},
    {Access::kColorAttachmentWrite, "color-attachment-write"},
    {Access::kDepthStencilAttachmentRead, "depth-stencil-attachment-read"},
    {Access::kDepthStencilAttachmentWrite, "depth-stencil-attachment-write"},
    {Access::kTransferRead, "transfer-read"},
    {Access::kTransferWrite, "transfer-write"},
    {Access::kHostRead, "host-read"},
    {Access::kConditionalRenderingRead, "conditional-rendering-read"},
}};

}  // namespace

std::string stage_names(Stage stages) {
    return bit_names(stages, kStageNames);
}

std::string access_names(Access access) {
    return bit_names(access, kAccessNames);
}

std::string layout_name(Layout layout) {
    switch (layout) {
        case Layout::kUndefined:
            return "undefined";
        case Layout::kGeneral:
            return "general";
        case Layout::kColorAttachment:
            return "color-attachment";
        case Layout::kDepthAttachment:
            return "depth-attachment";
        case Layout::kDepthReadOnly:
            return "depth-read-only";
        case Layout::kShaderReadOnly:
            return "shader-read-only";
        case Layout::kTransferSrc:
            return "transfer-src";
        case Layout::kTransferDst:
            return "transfer-dst";
    }
    return "?";
}

}  // namespace monoplane::graph
