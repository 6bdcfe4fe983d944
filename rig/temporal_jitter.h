// The sub-pixel jitter of TAA (Karis 2014) and its place in the rig's matrices. Fink et al. 2019
// Sect. 4.5 apply the same jitter, in pixels, to all three cameras; the mappings between C and
// the eyes (eq. 5, the depth pyramid's homography) are conjugated with it so they stay exact.
#pragma once

#include <cstdint>

#include <glm/ext/matrix_double3x3.hpp>
#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double2.hpp>

namespace monoplane::rig {

// Frames after which the sequence repeats.
constexpr std::uint64_t kJitterPeriod = 16;

// Frame n's offset in pixels (x right, y down), each coordinate in (-0.5, 0.5): the Halton
// sequence in bases 2 and 3, which covers the pixel evenly over any run of consecutive frames.
glm::dvec2 halton_jitter(std::uint64_t frame);

// Clip-space translation moving a view's image by `jitter_px` pixels over a viewport of
// `viewport_px` pixels: apply as jitter_matrix(...) * view_proj.
glm::dmat4 jitter_matrix(const glm::dvec2& jitter_px, const glm::dvec2& viewport_px);

// A homography between two views' pixels (x right, y down) for images jittered by the same
// pixel offset in both: T(j) * H * T(-j).
glm::dmat3 jittered_pixel_mapping(const glm::dmat3& pixel_mapping, const glm::dvec2& jitter_px);

}  // namespace monoplane::rig
