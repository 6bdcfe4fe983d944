// The render modes and anti-aliasing as the CLI, protocols, study databases, exports and
// bench.json spell them, one table each. Here because two sides that may not include each other
// name them: study/ (the modes a study compares, study/render_mode.h) and renderer/plan (the
// modes it draws, renderer/plan/render_choices.h). Names are stored in databases and outputs:
// never change one.
#pragma once

#include "common/name_table.h"

namespace monoplane {

// Every render mode that has a name. study::RenderMode takes its values from this enum;
// renderer/plan's RenderModeChoice is a Mode and a StereoPass, which render_choices.cpp maps
// onto it (hybrid-auto is the study's: a hybrid that chooses m every frame).
enum class NamedRenderMode {
    Stereo,
    StereoMultiview,
    StereoGs,
    StereoInstanced,
    Hybrid,
    HybridFarfield,
    HybridAuto
};

inline constexpr NameTable<NamedRenderMode> kRenderModeNames = {
    {NamedRenderMode::Stereo, "stereo"},
    {NamedRenderMode::StereoMultiview, "stereo-multiview"},
    {NamedRenderMode::StereoGs, "stereo-gs"},
    {NamedRenderMode::StereoInstanced, "stereo-instanced"},
    {NamedRenderMode::Hybrid, "hybrid"},
    {NamedRenderMode::HybridFarfield, "hybrid-farfield"},
    {NamedRenderMode::HybridAuto, "hybrid-auto"},
};

// Anti-aliasing as protocols' render.anti_aliasing and --anti-aliasing name it; the renderer's
// modes::AntiAliasing takes its values from this enum.
enum class NamedAntiAliasing { None, Taa, Msaa2, Msaa4, Msaa8 };

inline constexpr NameTable<NamedAntiAliasing> kAntiAliasingNames = {
    {NamedAntiAliasing::None, "none"},   {NamedAntiAliasing::Taa, "taa"},
    {NamedAntiAliasing::Msaa2, "msaa2"}, {NamedAntiAliasing::Msaa4, "msaa4"},
    {NamedAntiAliasing::Msaa8, "msaa8"},
};

}  // namespace monoplane
