// The render modes a study can compare, by the names the CLI, protocol
// files and the database use. The study only names them; the app maps them to renderer modes.
#pragma once

#include <span>
#include <string_view>

#include "common/render_mode_names.h"
#include "common/result.h"

namespace monoplane::study {

// Each value is the named mode's (common/render_mode_names.h), whose table holds the names.
enum class RenderMode {
    // "stereo": the reference, the full scene once per eye
    Stereo = static_cast<int>(NamedRenderMode::Stereo),
    // "stereo-multiview": both eyes in one pass (VK_KHR_multiview)
    StereoMultiview = static_cast<int>(NamedRenderMode::StereoMultiview),
    // "stereo-gs": both eyes in one pass via a geometry shader
    StereoGs = static_cast<int>(NamedRenderMode::StereoGs),
    // "stereo-instanced": both eyes in one pass, each draw's instance count doubled (the
    // instance picks the eye and its layer, as Unity's Single Pass Instanced)
    StereoInstanced = static_cast<int>(NamedRenderMode::StereoInstanced),
    // "hybrid": Fink et al. 2019, stereo up to the mono plane, mono beyond
    Hybrid = static_cast<int>(NamedRenderMode::Hybrid),
    // "hybrid-farfield": the engine-style far-field variant (papers/003)
    HybridFarfield = static_cast<int>(NamedRenderMode::HybridFarfield),
    // "hybrid-auto": hybrid whose renderer chooses m every frame within the protocol's [auto]
    // budget, never nearer than the trial's distance (issue 20; study/protocol_auto.h)
    HybridAuto = static_cast<int>(NamedRenderMode::HybridAuto),
};

// Every mode, in the order of the enum: for help texts and exhaustive tests.
std::span<const RenderMode> all_render_modes();

// The CLI name, e.g. "stereo-multiview". Names are stored in databases: never change one.
std::string_view render_mode_name(RenderMode mode);

// Exact, case-sensitive match of a CLI name; the error lists the valid names.
Result<RenderMode> parse_render_mode(std::string_view name);

}  // namespace monoplane::study
