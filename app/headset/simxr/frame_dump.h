// Writing what the application submitted to PNG files, for tests and dry runs to look at.
#pragma once

#include <filesystem>

#include <openxr/openxr.h>

#include "app/headset/simxr/runtime_state.h"

namespace monoplane::simxr {

// Copies the sub-image's rectangle of its swapchain's last released image to a PNG file: the
// bytes as stored (an sRGB image stays sRGB-encoded), BGRA swizzled to RGBA. The image is back in
// COLOR_ATTACHMENT_OPTIMAL and the queue idle when this returns. False (with a message on
// stderr) if the copy or the file fails.
bool dump_sub_image(Session& session, const XrSwapchainSubImage& sub_image,
                    const std::filesystem::path& file);

}  // namespace monoplane::simxr
