// Measured drift: how far image content moved between a reference rendering (stereo) and a test
// rendering (hybrid) inside a region, typically the pixels beyond the mono plane, where hybrid
// rendering reuses one eye's image and far content can land a pixel or two away from where
// stereo rendering puts it. SSIM (ssim.h) says that the images differ; this says by how many
// pixels and in which direction, which is what a drift tolerance is stated in.
//
// Method (block matching, as in PIV and optical-flow evaluation):
// - Channel: luma of both images (luma.h), so the two may have different channel counts.
// - Patches: square (2r + 1) x (2r + 1) patches, r = patch_radius, centred on a regular grid
//   c = (m + i * grid_step, m + j * grid_step) with m = patch_radius + search_radius, for every
//   centre whose patch and whole search window lie inside the image (c + m < width, height).
//   A patch is measured when every one of its pixels is in the mask and the population standard
//   deviation of its reference luma is >= min_luma_stddev: flat patches match anywhere equally
//   well and would only add noise.
// - Matching: the integer displacement d = (dx, dy), |dx|, |dy| <= search_radius, maximising
//   the zero-mean normalised cross-correlation (ZNCC, in [-1, 1]) between the reference patch at
//   c and the test patch at c + d. ZNCC ignores brightness offsets and contrast gains, so a
//   shading difference is not mistaken for motion. A flat test patch has ZNCC 0 (no evidence).
//   Ties go to the smaller |d|. Patches whose best ZNCC < min_correlation are rejected.
// - Sub-pixel: a 1-D parabola through the correlation at d - 1, d, d + 1, separately in x and
//   in y; skipped on an axis where d is on the search border (|d| = search_radius), since the
//   peak may lie beyond it. The correlation at d +- 1 is the mean of the forward match (reference
//   patch at c, test patch at c + d +- 1) and the backward one (test patch at c + d, reference
//   patch at c -+ 1): both peak at the same true displacement, but averaging them cancels the
//   asymmetry of one patch's own texture, which would otherwise bias the fit (on the unit test's
//   textures, identical images measured up to 0.16 px per patch instead of exactly 0).
//   The backward match reads reference pixels one step outside the patch, possibly unmasked;
//   the test patch may always reach outside the mask, because that is where drifted content goes.
//
// Sign convention: displacement = where the reference content appears in the test image minus
// where it is in the reference image, in pixels, x to the right, y down. If
// test(x, y) = reference(x - 2.3, y + 1.2), the content moved right by 2.3 and up by 1.2, and the
// displacement is (+2.3, -1.2).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "common/result.h"
#include "renderer/quality/image_view.h"

namespace monoplane::quality {

struct DriftOptions {
    // r: patches are (2r + 1) x (2r + 1) pixels; 7 gives 15 x 15. Must be >= 1.
    int patch_radius = 7;
    // Distance between neighbouring patch centres in pixels, in x and in y. Must be >= 1. The
    // default 24 leaves gaps between 15 x 15 patches, so the measurements are independent.
    int grid_step = 24;
    // Largest displacement searched, per axis, in pixels. Must be >= 0; 0 only tests whether the
    // content stayed in place (no sub-pixel refinement is possible then).
    int search_radius = 8;
    // On 0..255 luma: patches whose reference luma varies less are skipped. Must be >= 0.
    double min_luma_stddev = 4.0;
    // Matches whose best ZNCC is lower are rejected as unreliable (occlusion, content that changed
    // rather than moved, a shift beyond search_radius). Must be in [-1, 1].
    double min_correlation = 0.9;
};

// Statistics over the measured patches' displacement vectors. All zero when patches == 0, which is
// not an error: a mask without textured content, or an image too small for one patch plus its
// search window, has nothing to measure.
struct DriftMeasurement {
    // Patches measured, i.e. masked, textured, and matched with ZNCC >= min_correlation.
    std::size_t patches = 0;
    // Masked, textured patches dropped because their best ZNCC < min_correlation. Many of these
    // mean the drift exceeds search_radius or the content differs, not that it stayed in place.
    std::size_t rejected_patches = 0;
    // Euclidean magnitudes |d| in pixels: median (mean of the middle two for an even count),
    // 95th percentile (linear interpolation between order statistics at rank 0.95 (n - 1), as
    // numpy's default) and maximum.
    double median_px = 0.0;
    double p95_px = 0.0;
    double max_px = 0.0;
    // Mean displacement components in pixels: a common direction, e.g. a horizontal shift from
    // using one eye's image for both, shows here; drift in random directions averages out.
    double mean_dx_px = 0.0;
    double mean_dy_px = 0.0;
};

// Drift of test against reference (see the file comment for the method and the sign). mask is
// width * height bytes, row-major, non-zero = measure here (e.g. the pixels beyond the mono
// plane); empty = everywhere. The images may differ in channel count but not in size. Returns an
// error, never asserts, for malformed views, different sizes, a mask of the wrong size, or options
// out of range: such inputs can come from files and command lines.
Result<DriftMeasurement> measure_drift(const ImageView& reference, const ImageView& test,
                                       std::span<const std::uint8_t> mask,
                                       const DriftOptions& options = {});

}  // namespace monoplane::quality
