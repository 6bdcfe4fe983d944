// The single channel SSIM is computed on. SSIM is defined for one channel; for display images
// the usual choice is the luma of the encoded values, because that is what the structure and
// contrast a viewer sees are carried by. We use Rec. 709 (sRGB primaries) weights on the
// sRGB-encoded 8-bit values, without decoding to linear light and without rounding, so luma
// stays in [0, 255] and SSIM's constants C1 = (0.01 * 255)^2, C2 = (0.03 * 255)^2 apply as in
// Wang et al. 2004. (MATLAB's ssim on rgb2gray images uses Rec. 601 weights and rounds to
// 8 bits; values therefore differ slightly from ours on coloured images, not on grey ones.)
#pragma once

#include <vector>

#include "renderer/quality/image_view.h"

namespace monoplane::quality {

// Rec. 709 luma weights for R, G, B; they sum to 1, so grey (v, v, v) has luma v (up to
// rounding in the last bit).
inline constexpr double kLumaRed = 0.2126;
inline constexpr double kLumaGreen = 0.7152;
inline constexpr double kLumaBlue = 0.0722;

// Luma of every pixel, row-major, width * height values in [0, 255]. A 1-channel image is taken
// as luma already. Requires is_well_formed(image).
std::vector<double> luma(const ImageView& image);

}  // namespace monoplane::quality
