// View-frustum culling of chunk bounds on the CPU, in double precision: the reference the GPU
// culling pass (renderer/passes/culling) is tested against. The renderer itself does no
// per-chunk work on the CPU.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double3.hpp>
#include <glm/ext/vector_double4.hpp>

#include "scenes/scene.h"

namespace monoplane::modes {

// The six planes (a, b, c, d: inside where a x + b y + c z + d >= 0) of a Vulkan clip space
// 0 <= z <= w, extracted from a world -> clip matrix (Gribb and Hartmann).
std::array<glm::dvec4, 6> frustum_planes(const glm::dmat4& view_proj);

// True unless the box lies wholly outside one plane (conservative).
bool intersects(const std::array<glm::dvec4, 6>& planes, const scenes::Aabb& box);

// The chunk indices ordered by the distance from `viewer` to their bounds (0 inside), nearest
// first, ties by index: the culling pass lists draws in this order, so early depth testing
// rejects most hidden fragments before they are shaded (docs/benchmarks.md). Deterministic.
std::vector<std::uint32_t> front_to_back_order(const scenes::Scene& scene,
                                               const glm::dvec3& viewer);

// The frame's draw order: front_to_back_order for the opaque and alpha-masked chunks, and the
// blended ones (alphaMode BLEND) back to front by the distance from `viewer` to their bounds'
// centre, farthest first, ties by index. The culling pass keeps the order within each alpha class,
// so each view blends its surfaces farthest first ("over" is not commutative). A chunk is the
// unit: two blended chunks that interpenetrate, or one whose centre is nearer but which lies
// partly behind another, blend in the wrong order where they overlap (docs/scenes.md).
std::vector<std::uint32_t> draw_order(const scenes::Scene& scene, const glm::dvec3& viewer);

// Indices of the chunks whose bounds intersect the frustum of view_proj.
std::vector<std::uint32_t> visible_chunks(const scenes::Scene& scene, const glm::dmat4& view_proj);

}  // namespace monoplane::modes
