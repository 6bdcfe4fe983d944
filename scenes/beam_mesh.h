// Long straight beams: prisms with a rectangular (optionally chamfered) cross-section and flat
// shading, so every edge stays a crisp line (the BEAMS scene, papers/000 Fig. 6).
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "scenes/chunk_builder.h"

namespace monoplane::scenes {

struct Beam {
    glm::vec3 start{0.0f};
    glm::vec3 end{0.0f, 0.0f, -1.0f};
    float width = 0.1f;   // across, perpendicular to the axis and to up
    float height = 0.1f;  // along up (projected perpendicular to the axis)
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    std::uint32_t albedo_rgba8 = 0xffffffffu;
    std::uint32_t material_packed = 0;
};

struct BeamTessellation {
    // A beam is cut into sections of at most this length, each its own piece, so that long
    // beams fall into compact chunks along their length.
    float section_length = 8.0f;
    // Each side face is subdivided along the axis into segments of at most this length.
    float segment_length = 8.0f;
    // Chamfered corners turn the four side faces into eight.
    bool chamfered = false;
};

// Adds the beam as pieces of the builder; returns the number of triangles added.
std::size_t add_beam(ChunkBuilder& builder, const Beam& beam, const BeamTessellation& tessellation);

}  // namespace monoplane::scenes
