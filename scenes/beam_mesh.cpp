#include "scenes/beam_mesh.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "common/programming_error.h"

namespace monoplane::scenes {
namespace {

// The cross-section as a counter-clockwise polygon in (side, up) coordinates.
std::vector<glm::vec2> cross_section(float width, float height, bool chamfered) {
    const float w = 0.5f * width;
    const float h = 0.5f * height;
    if (!chamfered) return {{w, -h}, {w, h}, {-w, h}, {-w, -h}};
    const float c = 0.15f * std::min(width, height);
    return {{w, -h + c}, {w, h - c},   {w - c, h},   {-w + c, h},
            {-w, h - c}, {-w, -h + c}, {-w + c, -h}, {w - c, -h}};
}

struct Frame {
    glm::vec3 axis;
    glm::vec3 side;
    glm::vec3 up;
};

Frame frame_of(const Beam& beam) {
    Frame frame;
    frame.axis = glm::normalize(beam.end - beam.start);
    glm::vec3 side = glm::cross(frame.axis, beam.up);
    if (glm::dot(side, side) < 1e-8f) {  // a vertical beam with up = +y: any side will do
        side = glm::cross(frame.axis, glm::vec3(0.0f, 0.0f, 1.0f));
    }
    frame.side = glm::normalize(side);
    frame.up = glm::cross(frame.side, frame.axis);
    return frame;
}

}  // namespace

std::size_t add_beam(ChunkBuilder& builder, const Beam& beam,
                     const BeamTessellation& tessellation) {
    const glm::vec3 span = beam.end - beam.start;
    const float length = glm::length(span);
    MONOPLANE_EXPECTS(length > 0.0f && tessellation.segment_length > 0.0f);
    const Frame frame = frame_of(beam);
    const std::vector<glm::vec2> profile =
        cross_section(beam.width, beam.height, tessellation.chamfered);
    const int corners = static_cast<int>(profile.size());

    const int segments =
        std::max(1, static_cast<int>(std::ceil(length / tessellation.segment_length)));
    const int segments_per_section =
        std::max(1, static_cast<int>(std::floor(tessellation.section_length /
                                                (length / static_cast<float>(segments)))));

    // Boundary positions come from the global boundary number alone, so neighbouring sections
    // share bit-identical vertices and the beam is watertight across chunks.
    const auto centre_at = [&](int boundary) {
        return beam.start + span * (static_cast<float>(boundary) / static_cast<float>(segments));
    };
    const auto offset_of = [&](const glm::vec2& p) { return frame.side * p.x + frame.up * p.y; };

    Vertex vertex{};
    vertex.albedo_rgba8 = beam.albedo_rgba8;
    vertex.material_packed = beam.material_packed;
    const std::size_t triangles_before = builder.triangle_count();

    for (int first = 0; first < segments; first += segments_per_section) {
        const int last = std::min(segments, first + segments_per_section);
        builder.begin_piece();
        for (int k = 0; k < corners; ++k) {
            const glm::vec2 a = profile[static_cast<std::size_t>(k)];
            const glm::vec2 b = profile[static_cast<std::size_t>((k + 1) % corners)];
            const glm::vec2 edge = b - a;
            vertex.normal = glm::normalize(frame.side * edge.y - frame.up * edge.x);
            const glm::vec3 offset_a = offset_of(a);
            const glm::vec3 offset_b = offset_of(b);
            const std::uint32_t base = builder.piece_vertex_count();
            for (int boundary = first; boundary <= last; ++boundary) {
                const glm::vec3 centre = centre_at(boundary);
                vertex.position = centre + offset_a;
                builder.add_vertex(vertex);
                vertex.position = centre + offset_b;
                builder.add_vertex(vertex);
            }
            for (int s = 0; s < last - first; ++s) {
                const std::uint32_t i = base + 2 * static_cast<std::uint32_t>(s);
                builder.add_quad(i, i + 1, i + 3, i + 2);
            }
        }
        const auto add_cap = [&](int boundary, float direction) {
            vertex.normal = frame.axis * direction;
            const std::uint32_t base = builder.piece_vertex_count();
            for (const glm::vec2& p : profile) {
                vertex.position = centre_at(boundary) + offset_of(p);
                builder.add_vertex(vertex);
            }
            for (int k = 1; k + 1 < corners; ++k) {
                builder.add_triangle(base, base + static_cast<std::uint32_t>(k),
                                     base + static_cast<std::uint32_t>(k + 1));
            }
        };
        if (first == 0) add_cap(0, -1.0f);
        if (last == segments) add_cap(segments, 1.0f);
    }
    return builder.triangle_count() - triangles_before;
}

}  // namespace monoplane::scenes
