#include "scenes/sphere_mesh.h"

#include <cmath>
#include <numbers>

#include "common/programming_error.h"

namespace monoplane::scenes {

void add_sphere(ChunkBuilder& builder, glm::vec3 centre, float radius,
                const SphereTessellation& tessellation, std::uint32_t albedo_rgba8,
                std::uint32_t material_packed) {
    const int segments = tessellation.segments;
    const int rings = tessellation.rings;
    MONOPLANE_EXPECTS(segments >= 3 && rings >= 2);
    builder.begin_piece();
    Vertex vertex{};
    vertex.albedo_rgba8 = albedo_rgba8;
    vertex.material_packed = material_packed;
    const auto add = [&](glm::vec3 direction) {
        vertex.normal = direction;
        vertex.position = centre + radius * direction;
        return builder.add_vertex(vertex);
    };
    const std::uint32_t north = add({0.0f, 1.0f, 0.0f});
    const std::uint32_t south = add({0.0f, -1.0f, 0.0f});
    const std::uint32_t first_ring = builder.piece_vertex_count();
    for (int ring = 1; ring < rings; ++ring) {
        const double polar = std::numbers::pi * ring / rings;
        for (int s = 0; s < segments; ++s) {
            const double azimuth = 2.0 * std::numbers::pi * s / segments;
            add({static_cast<float>(std::sin(polar) * std::cos(azimuth)),
                 static_cast<float>(std::cos(polar)),
                 static_cast<float>(std::sin(polar) * std::sin(azimuth))});
        }
    }
    const auto at = [&](int ring, int s) {  // ring in [1, rings - 1]
        return first_ring + static_cast<std::uint32_t>((ring - 1) * segments + s % segments);
    };
    for (int s = 0; s < segments; ++s) {
        builder.add_triangle(north, at(1, s), at(1, s + 1));
        builder.add_triangle(south, at(rings - 1, s), at(rings - 1, s + 1));
        for (int ring = 1; ring + 1 < rings; ++ring) {
            builder.add_quad(at(ring, s), at(ring, s + 1), at(ring + 1, s + 1), at(ring + 1, s));
        }
    }
}

}  // namespace monoplane::scenes
