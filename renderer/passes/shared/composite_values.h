// What the composite (renderer/passes/composite/composite_unit.cpp) needs of a frame beyond its
// images: how C's image maps into each eye this frame, which the renderer works out from the rig
// (eq. 5 with the jitter, eq. 8, eq. 9) or the far field's offsets (UnitFrameValues::composite).
// Plain values, Vulkan-free.
#pragma once

#include <array>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

namespace monoplane::passes {

// How C's image reaches an eye; the shader's mode (composite_body.glsl).
enum class CompositeMapping {
    kProjective = 0,  // through M_{E->C} at the mono plane, bilinear: monoplane's hybrid
    kOffsetCopy = 1,  // a constant integer pixel offset, nearest: the engine-style far field
    kNothing = 2,     // leave the far region black (debug view "stereo only")
};

// One eye's mapping.
struct CompositeEyeMapping {
    glm::mat4 eye_to_mono{1.0f};  // M_{E->C} between the jittered clip spaces, float32 as the GPU
    glm::vec2 uv_scale{1.0f};     // C's viewport / allocation (eq. 8)
    glm::ivec2 pixel_offset{0};   // kOffsetCopy's offset in pixels
    // C's NDC velocity -> the eye's (diagonal): 1/2 S of eq. 9 for kProjective, C's size over
    // the eye's for kOffsetCopy. Read only with TAA (the composite then writes velocity).
    glm::vec2 velocity_scale{1.0f};
};

struct CompositeValues {
    CompositeMapping mapping = CompositeMapping::kProjective;
    std::array<CompositeEyeMapping, 2> eyes;  // left, right (plan::eye_index)
    glm::vec2 mono_allocation{1.0f};          // C's image size in pixels
    float tint = 0.0f;                        // debug view "mono region tinted": 0 off, 1 full
    bool cover_all_pixels = false;            // debug view "mono only": ignore the near content
};

}  // namespace monoplane::passes
