// --anti-aliasing, --ssao and --stereo-pass, as `render` and `bench` take them.
#pragma once

#include <string>

#include "renderer/modes/mode_renderer.h"

namespace monoplane::app {

// Sets options.anti_aliasing and options.ssao from the flags' values ("none|taa|msaa2|msaa4|
// msaa8", "off|per-eye|stereo"); throws UserError naming the flag for any other value.
void apply_image_quality_flags(const std::string& anti_aliasing, const std::string& ssao,
                               modes::RendererOptions& options);

// --stereo-pass's value ("two|multiview|gs"); throws UserError naming the flag for any other.
plan::StereoPass parse_stereo_pass_flag(const std::string& stereo_pass);

}  // namespace monoplane::app
