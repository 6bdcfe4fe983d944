// Stereo inconsistency of ambient occlusion, the error map E of papers/002 (Shi, Billeter,
// Eisemann 2022) Sect. 4.1: every left pixel p that shows a surface point the right eye sees too
// is compared with the right view's AO bilinearly interpolated where that point lands,
// E(p) = |A(p) - I(p)|. A stereo-consistent AO (papers/002 Sect. 3) gives E close to zero; a
// per-eye SSAO does not, because each eye estimates occlusion from what it alone sees.
//
// Method, per left pixel p (pixel (i, j) is at NDC ((i + 0.5) / width * 2 - 1,
// (j + 0.5) / height * 2 - 1), row 0 at the top, Vulkan's y down):
// - Position: the world point X of p from its linear depth d: the ray from camera_position
//   through inverse(view_proj) * (ndc, 0.5, 1) meets the plane dot(X - head.position,
//   head.forward) = d. Sky pixels (d >= kSkyLinearDepth) have no point and are counted as sky.
// - Visibility, reverse reprojection with back-check (papers/002 Sect. 3.1 and Fig. 5d): X is
//   projected into the right view at the continuous pixel position q (pixel-centre coordinates:
//   pixel (i, j) is at q = (i, j)). X is seen only by the left eye (one_eye_only) if it lies
//   behind the right eye or outside its frustum (q beyond the image's outer edges, depth outside
//   [0, 1]), or if the right pixel p* nearest to q is sky, or if p*'s own world point, projected
//   back into the left view, lands farther than back_check_px (Euclidean, in left pixels) from p:
//   then the right eye sees something else there, typically a nearer occluder.
// - Normal check (papers/002 Sect. 4.1): the normal of p and those of the right pixels that
//   enter I(p), the bilinear footprint of q, must all lie within normal_threshold_deg; a
//   footprint pixel that is sky or outside the image, or a normal that cannot be reconstructed,
//   fails too (normal_rejected). This keeps edges where interpolation mixes two surfaces, e.g.
//   a crease seen across two pixels, out of the error. (A footprint that straddles a silhouette
//   onto a parallel surface behind, e.g. a box's front face and the wall, passes: normals cannot
//   tell, and such pixels carry part of the difference between the two surfaces' AO.) A pixel's
//   normal is the cross product of its horizontal and vertical position differences, each the
//   shorter of the forward and backward difference to a non-sky neighbour (so it does not reach
//   across a depth step), turned towards the eye that sees it.
// - Footprint: the 2 x 2 pixels (floor(q), floor(q) + 1) as a GPU's bilinear fetch, except that
//   a column or row whose bilinear weight is zero is left out, after coordinates within 1e-4 px
//   of a pixel centre are snapped onto it. In a stereo pair with parallel eyes of the same
//   vertical field of view every q lies on a pixel row, and whether floor() picks the row above
//   or the one below would otherwise depend on rounding; papers/002's "four nearest neighbours"
//   are not unique there either. A consequence: with only horizontal parallax the interpolation
//   never reads across a horizontal crease (floor and wall), so such pixels are compared.
// - Error: I(p) = bilinear interpolation of the right AO at q, E(p) = |A(p) - I(p)|.
//
// Every left pixel falls in exactly one class: compared + sky + one_eye_only + normal_rejected
// = width * height.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double3.hpp>

#include "common/result.h"

namespace monoplane::quality {

// Linear depths at or beyond this are sky (no surface), as the forward pass writes them.
inline constexpr float kSkyLinearDepth = 1e29f;

// One eye's AO as rendered: the matrices the rasteriser used and per-pixel values.
struct StereoAoView {
    std::uint32_t width = 0, height = 0;
    // World -> clip, Vulkan conventions: reversed Z (near -> 1, far -> 0), clip y down. Must be a
    // perspective projection whose centre is camera_position.
    glm::dmat4 view_proj{1.0};
    glm::dvec3 camera_position{0.0};  // the eye in world space
    // Row-major, row 0 at the top, width * height values: metres
    // d = dot(X - head.position, head.forward) > 0, or >= kSkyLinearDepth (+inf too) for sky.
    std::vector<float> linear_depth;
    // [0, 1] per pixel (values outside are compared as they are); ignored at sky pixels.
    std::vector<float> ao;
};

// The head both eyes belong to: the linear depths are distances along forward (unit length)
// from the plane through position.
struct StereoHead {
    glm::dvec3 position{0.0};
    glm::dvec3 forward{0.0, 0.0, -1.0};
};

struct InconsistencyOptions {
    // Largest round-trip distance, in left pixels, of the back-check (papers/002: one pixel).
    // Must be > 0.
    double back_check_px = 1.0;
    // Largest angle between p's normal and a footprint normal (papers/002: 6 degrees). Must be in
    // [0, 180]; 180 turns the normal check off (sky and out-of-image footprints still fail).
    double normal_threshold_deg = 6.0;
};

// How a left pixel was treated.
enum class InconsistencyClass : std::uint8_t {
    compared,         // visible in both eyes and normal check passed: error holds E(p)
    sky,              // no surface at p
    one_eye_only,     // failed the visibility test (purple in papers/002 Fig. 9)
    normal_rejected,  // visible in both eyes but the normal check failed
};

struct InconsistencyMap {
    std::uint32_t width = 0, height = 0;      // the left view's
    std::vector<float> error;                 // E(p) per left pixel; NaN where not compared
    std::vector<InconsistencyClass> classes;  // per left pixel, row-major like error
    double mean = 0.0;                        // over compared pixels (0 when none)
    double max = 0.0;                         // over compared pixels (0 when none)
    std::size_t compared = 0, sky = 0, one_eye_only = 0, normal_rejected = 0;
};

// The left view's inconsistency error map against the right view (see the file comment). The
// views may differ in size. May be called with any input: returns an error, never asserts, for an
// empty view, depth or AO vectors of the wrong length, a NaN or non-positive depth, a non-finite
// AO at a non-sky pixel, a view_proj that is not a finite, invertible perspective projection
// centred on camera_position (within 1 mm), a non-unit or non-finite head, a non-sky pixel whose
// ray never reaches its depth, or options out of range.
Result<InconsistencyMap> stereo_inconsistency(const StereoAoView& left, const StereoAoView& right,
                                              const StereoHead& head,
                                              const InconsistencyOptions& options = {});

// The heat map's colours for pixels without an error. Points seen by one eye only are purple,
// as in papers/002 Fig. 9; no inferno colour has this much blue, so it cannot pass for an error.
using Rgba8 = std::array<std::uint8_t, 4>;
inline constexpr Rgba8 kOneEyeOnlyRgba = {160, 32, 240, 255};
inline constexpr Rgba8 kNoErrorRgba = {0, 0, 0, 255};  // sky and normal-rejected pixels

// RGBA8 picture of the map (width * height * 4 bytes, row-major, opaque): compared pixels are
// inferno(clamp(E * scale, 0, 1)) (colormap.h; papers/002 magnifies errors 20x, so E >= 0.05
// saturates to pale yellow), pixels seen by one eye only purple (kOneEyeOnlyRgba), sky and
// normal-rejected pixels black (kNoErrorRgba). Requires a map from stereo_inconsistency and
// scale > 0 and finite (checked in every build; aborts otherwise).
std::vector<std::uint8_t> inconsistency_heat_map_rgba(const InconsistencyMap& map,
                                                      float scale = 20.0f);

}  // namespace monoplane::quality
