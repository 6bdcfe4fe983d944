#include "study/render_mode.h"

#include <array>
#include <cassert>
#include <string>

namespace monoplane::study {
namespace {

struct NamedMode {
    RenderMode mode;
    std::string_view name;
};

constexpr std::array<NamedMode, 6> kNamedModes = {{
    {RenderMode::Stereo, "stereo"},
    {RenderMode::StereoMultiview, "stereo-multiview"},
    {RenderMode::StereoGs, "stereo-gs"},
    {RenderMode::Hybrid, "hybrid"},
    {RenderMode::HybridFarfield, "hybrid-farfield"},
    {RenderMode::HybridAuto, "hybrid-auto"},
}};

constexpr std::array<RenderMode, 6> kAllModes = {
    RenderMode::Stereo, RenderMode::StereoMultiview, RenderMode::StereoGs,
    RenderMode::Hybrid, RenderMode::HybridFarfield,  RenderMode::HybridAuto};

}  // namespace

std::span<const RenderMode> all_render_modes() {
    return kAllModes;
}

std::string_view render_mode_name(RenderMode mode) {
    for (const NamedMode& named : kNamedModes) {
        if (named.mode == mode) return named.name;
    }
    assert(false && "RenderMode value outside the enum");
    return "invalid";
}

Result<RenderMode> parse_render_mode(std::string_view name) {
    std::string valid;
    for (const NamedMode& named : kNamedModes) {
        if (named.name == name) return named.mode;
        valid += (valid.empty() ? "" : ", ") + std::string(named.name);
    }
    return Error{"unknown render mode '" + std::string(name) + "' (valid: " + valid + ")"};
}

}  // namespace monoplane::study
