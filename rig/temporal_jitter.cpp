#include "rig/temporal_jitter.h"

namespace monoplane::rig {
namespace {

// The radical inverse of index in `base`: its digits mirrored behind the point.
double radical_inverse(std::uint64_t index, std::uint64_t base) {
    double result = 0.0;
    double digit_weight = 1.0 / static_cast<double>(base);
    while (index > 0) {
        result += static_cast<double>(index % base) * digit_weight;
        index /= base;
        digit_weight /= static_cast<double>(base);
    }
    return result;
}

}  // namespace

glm::dvec2 halton_jitter(std::uint64_t frame) {
    // Index 0 of the Halton sequence is the corner (0, 0); start at 1 so every sample is inside.
    const std::uint64_t index = frame % kJitterPeriod + 1;
    return {radical_inverse(index, 2) - 0.5, radical_inverse(index, 3) - 0.5};
}

glm::dmat4 jitter_matrix(const glm::dvec2& jitter_px, const glm::dvec2& viewport_px) {
    glm::dmat4 translation(1.0);
    // clip.xy += offset_ndc * clip.w: NDC spans 2 over the viewport.
    translation[3][0] = 2.0 * jitter_px.x / viewport_px.x;
    translation[3][1] = 2.0 * jitter_px.y / viewport_px.y;
    return translation;
}

glm::dmat3 jittered_pixel_mapping(const glm::dmat3& pixel_mapping, const glm::dvec2& jitter_px) {
    glm::dmat3 forward(1.0);
    forward[2][0] = jitter_px.x;
    forward[2][1] = jitter_px.y;
    glm::dmat3 back(1.0);
    back[2][0] = -jitter_px.x;
    back[2][1] = -jitter_px.y;
    return forward * pixel_mapping * back;
}

}  // namespace monoplane::rig
