// The SPIR-V of a forward pass's pipelines (forward_pass.h): the one-view shaders, or one
// single-pass stereo form's variants of them (compiled from the same sources with that form's
// define, renderer/passes/CMakeLists.txt).
#pragma once

#include <cstdint>
#include <span>

#include "renderer/passes/forward/forward_pass.h"

namespace monoplane::passes {

using Spirv = std::span<const std::uint32_t>;

struct ForwardShaders {
    Spirv vertex, show_routing_vertex, sky_vertex;
    // The geometry-shader form only; empty (no geometry stage) in every other.
    Spirv geometry, show_routing_geometry, sky_geometry;
    // The fragment shaders, with velocity output where the configuration asks for it.
    Spirv forward, show_routing, sky;
    Spirv mask_hidden;  // one-view passes' (C's) mask of pixels hidden in both eyes
    // The depth pre-pass of alphaMode MASK chunks: the alpha test (alpha to coverage with MSAA).
    Spirv masked_depth;
    // Hybrid's blended chunks nearer than m, drawn into the eyes after the composite.
    Spirv after_composite;
};

ForwardShaders forward_shaders(const ForwardConfig& config);

}  // namespace monoplane::passes
