// The synchronisation vocabulary of the render graph, without Vulkan: pipeline stages, memory
// accesses and image layouts as the compile step reasons about them. Each value stands for the
// synchronization2 flag of the same name (VK_PIPELINE_STAGE_2_*, VK_ACCESS_2_*, VK_IMAGE_LAYOUT_*);
// the executor (renderer/executor/graph_executor.cpp) is the one place that translates.
//
// When may this be called: any time; pure values.
#pragma once

#include <cstdint>
#include <string>

namespace monoplane::graph {

// Pipeline stages, as a bit mask.
enum class Stage : std::uint32_t {
    kNone = 0,
    kDrawIndirect = 1u << 0,
    kVertexShader = 1u << 1,
    kGeometryShader = 1u << 2,
    kEarlyFragmentTests = 1u << 3,
    kFragmentShader = 1u << 4,
    kLateFragmentTests = 1u << 5,
    kColorAttachmentOutput = 1u << 6,
    kComputeShader = 1u << 7,
    kTransfer = 1u << 8,  // copies, blits, clears and fills
    kConditionalRendering = 1u << 9,
    kHost = 1u << 10,
};

// Memory accesses, as a bit mask.
enum class Access : std::uint32_t {
    kNone = 0,
    kIndirectCommandRead = 1u << 0,
    kUniformRead = 1u << 1,
    kShaderSampledRead = 1u << 2,
    kShaderStorageRead = 1u << 3,
    kShaderStorageWrite = 1u << 4,
    kColorAttachmentRead = 1u << 5,
    kColorAttachmentWrite = 1u << 6,
    kDepthStencilAttachmentRead = 1u << 7,
    kDepthStencilAttachmentWrite = 1u << 8,
    kTransferRead = 1u << 9,
    kTransferWrite = 1u << 10,
    kHostRead = 1u << 11,
    kConditionalRenderingRead = 1u << 12,
};

constexpr Stage operator|(Stage a, Stage b) {
    return static_cast<Stage>(static_cast<std::uint32_t>(a) | static_cast<std::uint32_t>(b));
}
constexpr Stage operator&(Stage a, Stage b) {
    return static_cast<Stage>(static_cast<std::uint32_t>(a) & static_cast<std::uint32_t>(b));
}
constexpr Stage& operator|=(Stage& a, Stage b) {
    return a = a | b;
}
constexpr Access operator|(Access a, Access b) {
    return static_cast<Access>(static_cast<std::uint32_t>(a) | static_cast<std::uint32_t>(b));
}
constexpr Access operator&(Access a, Access b) {
    return static_cast<Access>(static_cast<std::uint32_t>(a) & static_cast<std::uint32_t>(b));
}
constexpr Access& operator|=(Access& a, Access b) {
    return a = a | b;
}
constexpr bool any(Stage s) {
    return s != Stage::kNone;
}
constexpr bool any(Access a) {
    return a != Access::kNone;
}
// Whether every bit of `part` is in `whole`.
constexpr bool covers(Stage whole, Stage part) {
    return (whole & part) == part;
}
constexpr bool covers(Access whole, Access part) {
    return (whole & part) == part;
}

// The accesses that write memory (a hazard source for every later access).
constexpr Access kWriteAccesses = Access::kShaderStorageWrite | Access::kColorAttachmentWrite |
                                  Access::kDepthStencilAttachmentWrite | Access::kTransferWrite;

enum class Layout : std::uint8_t {
    kUndefined,  // contents discarded
    kGeneral,    // storage images
    kColorAttachment,
    kDepthAttachment,
    kDepthReadOnly,  // a depth image sampled (and possibly depth-tested without writes)
    kShaderReadOnly,
    kTransferSrc,
    kTransferDst,
};

// "color-attachment-output|fragment-shader", "shader-sampled-read", "shader-read-only": for test
// messages and `render --json`'s compiled barriers.
std::string stage_names(Stage stages);
std::string access_names(Access access);
std::string layout_name(Layout layout);

}  // namespace monoplane::graph
