#include "renderer/plan/render_choices.h"

#include "renderer/plan/name_table.h"

namespace monoplane::modes {

namespace {

// Each enum's CLI names, for parse_* and *_name alike.
constexpr NameTable<Mode> kModeNames = {{Mode::kStereo, "stereo"},
                                        {Mode::kHybrid, "hybrid"},
                                        {Mode::kHybridFarfield, "hybrid-farfield"}};
constexpr NameTable<StereoPass> kStereoPassNames = {{StereoPass::kTwoPasses, "two"},
                                                    {StereoPass::kMultiview, "multiview"},
                                                    {StereoPass::kGeometryShader, "gs"}};
// The stereo mode's name with each stereo pass.
constexpr NameTable<StereoPass> kStereoModeNames = {{StereoPass::kTwoPasses, "stereo"},
                                                    {StereoPass::kMultiview, "stereo-multiview"},
                                                    {StereoPass::kGeometryShader, "stereo-gs"}};
constexpr NameTable<DebugView> kDebugViewNames = {{DebugView::kNone, "none"},
                                                  {DebugView::kTintMono, "tint-mono"},
                                                  {DebugView::kStereoOnly, "stereo-only"},
                                                  {DebugView::kMonoOnly, "mono-only"},
                                                  {DebugView::kRouting, "routing"}};
constexpr NameTable<MonoCulling> kMonoCullingNames = {
    {MonoCulling::kNoOpt, "no-opt"},
    {MonoCulling::kDiscard, "discard"},
    {MonoCulling::kOcclusionCull, "occlusion-cull"},
    {MonoCulling::kAuto, "auto"}};
constexpr NameTable<AntiAliasing> kAntiAliasingNames = {{AntiAliasing::kNone, "none"},
                                                        {AntiAliasing::kTaa, "taa"},
                                                        {AntiAliasing::kMsaa2, "msaa2"},
                                                        {AntiAliasing::kMsaa4, "msaa4"},
                                                        {AntiAliasing::kMsaa8, "msaa8"}};

}  // namespace

std::optional<Mode> parse_mode(const std::string& name) {
    return parse_name(kModeNames, name);
}

std::string mode_name(Mode mode) {
    return name_of(kModeNames, mode);
}

std::optional<StereoPass> parse_stereo_pass(const std::string& name) {
    return parse_name(kStereoPassNames, name);
}

std::string stereo_pass_name(StereoPass pass) {
    return name_of(kStereoPassNames, pass);
}

std::optional<RenderModeChoice> parse_render_mode(const std::string& name) {
    if (const auto pass = parse_name(kStereoModeNames, name)) {
        return RenderModeChoice{Mode::kStereo, *pass};
    }
    if (const auto mode = parse_mode(name)) return RenderModeChoice{*mode, StereoPass::kTwoPasses};
    return std::nullopt;
}

std::string render_mode_name(const RenderModeChoice& choice) {
    if (choice.mode != Mode::kStereo) return mode_name(choice.mode);
    return name_of(kStereoModeNames, choice.stereo_pass);
}

std::optional<DebugView> parse_debug_view(const std::string& name) {
    return parse_name(kDebugViewNames, name);
}

std::optional<MonoCulling> parse_mono_culling(const std::string& name) {
    return parse_name(kMonoCullingNames, name);
}

std::string mono_culling_name(MonoCulling culling) {
    return name_of(kMonoCullingNames, culling);
}

std::optional<AntiAliasing> parse_anti_aliasing(const std::string& name) {
    return parse_name(kAntiAliasingNames, name);
}

std::string anti_aliasing_name(AntiAliasing aa) {
    return name_of(kAntiAliasingNames, aa);
}

}  // namespace monoplane::modes
