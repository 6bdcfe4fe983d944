// Writing what the application submitted to files, for tests and dry runs to look at: colour as
// PNG, depth (XR_KHR_composition_layer_depth) as PFM.
#pragma once

#include <filesystem>

#include <openxr/openxr.h>

#include "simxr/runtime_state.h"

namespace monoplane::simxr {

// Copies the sub-image's rectangle of its swapchain's last released image to a PNG file: the
// bytes as stored (an sRGB image stays sRGB-encoded), BGRA swizzled to RGBA. The image is back in
// COLOR_ATTACHMENT_OPTIMAL and the queue idle when this returns. False (with a message on
// stderr) if the copy or the file fails.
bool dump_sub_image(Session& session, const XrSwapchainSubImage& sub_image,
                    const std::filesystem::path& file);

// Copies the depth sub-image (XR_KHR_composition_layer_depth) of its swapchain's last released
// image and writes each texel's distance in front of the eye, in metres (view space -z, decoded
// with the structure's minDepth, maxDepth, nearZ and farZ; +inf on an infinite plane) to a
// one-channel PFM file in the host's byte order (the scale's sign says which). The image is back in
// DEPTH_STENCIL_ATTACHMENT_OPTIMAL and the queue idle when this returns. Call only with a structure
// xrEndFrame has checked. False (with a message on stderr) if the copy or the file fails.
bool dump_depth_sub_image(Session& session, const XrCompositionLayerDepthInfoKHR& depth,
                          const std::filesystem::path& file);

}  // namespace monoplane::simxr
