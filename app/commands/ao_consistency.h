// The stereo consistency of a rendered frame's ambient occlusion (papers/002 Sect. 4.1): the
// inconsistency error E(p) of the left eye against the right, its mean and a heat map.
#pragma once

#include <filesystem>

#include "renderer/modes/mode_renderer.h"
#include "renderer/quality/stereo_inconsistency.h"

namespace monoplane::app {

// The renderer's last frame must have read back AO and linear depth (RendererOptions
// read_back_ao, read_back_depth). Throws UserError when the metric refuses its inputs.
quality::InconsistencyMap ao_inconsistency(const modes::ModeRenderer& renderer,
                                           const modes::FrameInputs& inputs);

// Writes ao_left.png, ao_right.png (AO as grey) and ao_inconsistency.png (E magnified 20x,
// inferno; purple where one eye alone sees the surface) into `out`.
void write_ao_pictures(const modes::ModeRenderer& renderer, const quality::InconsistencyMap& map,
                       const std::filesystem::path& out);

}  // namespace monoplane::app
