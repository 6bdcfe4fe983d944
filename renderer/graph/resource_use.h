// How a step uses an image or a buffer. Each use stands for one (stages, accesses, layout) triple:
// passes say what they do ("sampled by a fragment shader"), never which barrier that needs; the
// compile step (frame_graph.h) derives the barriers from consecutive uses.
//
// When may this be called: any time; pure values.
#pragma once

#include <cstdint>
#include <string>

#include "renderer/graph/sync_scope.h"

namespace monoplane::graph {

enum class Use : std::uint8_t {
    // Images
    kColorWrite,           // a colour attachment written without reading (clear or don't-care)
    kColorBlend,           // a colour attachment loaded and blended into
    kDepthWrite,           // a depth attachment tested and written
    kDepthTest,            // a depth attachment tested, not written (apply and composite passes)
    kDepthSampledCompute,  // a depth image sampled by a compute shader
    kSampledFragment,      // sampled by a fragment shader
    kSampledCompute,       // sampled by a compute shader
    kSampledAny,           // sampled by fragment and compute shaders (bound to both)
    kGeneralSampled,  // a storage image (general layout) sampled by fragment or compute shaders
    kStorageRead,     // compute shader image/buffer loads
    kStorageWrite,    // compute shader image/buffer stores (read-modify-write included)
    kTransferSrc,     // copied from
    kTransferDst,     // copied or cleared into
    // Buffers only
    kIndirectArgs,  // indirect draw parameters and counts (also read by the draws' shaders)
    kConditional,   // conditional-rendering predicates
    kHostRead,      // read by the host after the frame's fence
};

struct UseScope {
    Stage stages = Stage::kNone;
    Access access = Access::kNone;
    Layout layout = Layout::kUndefined;  // images only
    bool writes = false;                 // the use writes memory
};

// The (stages, accesses, layout) a use stands for.
UseScope use_scope(Use use);

// "color-write", "sampled-fragment", ...
std::string use_name(Use use);

}  // namespace monoplane::graph
