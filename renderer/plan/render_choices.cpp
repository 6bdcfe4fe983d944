#include "renderer/plan/render_choices.h"

#include "common/name_table.h"

namespace monoplane::plan {

namespace {

// The named render modes (common/render_mode_names.h) as the renderer draws them: stereo's four
// names are its stereo passes; the hybrid modes draw their near region in two passes by default.
struct ModeOfName {
    NamedRenderMode named;
    RenderModeChoice choice;
};
constexpr ModeOfName kModesOfNames[] = {
    {NamedRenderMode::Stereo, {Mode::kStereo, StereoPass::kTwoPasses}},
    {NamedRenderMode::StereoMultiview, {Mode::kStereo, StereoPass::kMultiview}},
    {NamedRenderMode::StereoGs, {Mode::kStereo, StereoPass::kGeometryShader}},
    {NamedRenderMode::StereoInstanced, {Mode::kStereo, StereoPass::kInstanced}},
    {NamedRenderMode::Hybrid, {Mode::kHybrid, StereoPass::kTwoPasses}},
    {NamedRenderMode::HybridFarfield, {Mode::kHybridFarfield, StereoPass::kTwoPasses}},
};

// The choices' own names, for parse_* and *_name alike.
constexpr NameTable<StereoPass> kStereoPassNames = {{StereoPass::kTwoPasses, "two"},
                                                    {StereoPass::kMultiview, "multiview"},
                                                    {StereoPass::kGeometryShader, "gs"},
                                                    {StereoPass::kInstanced, "instanced"}};
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

}  // namespace

std::optional<Mode> parse_mode(const std::string& name) {
    // A mode's name is its render mode's with two passes: "stereo-gs" names no Mode.
    const auto choice = parse_render_mode(name);
    if (!choice || choice->stereo_pass != StereoPass::kTwoPasses) return std::nullopt;
    return choice->mode;
}

std::string mode_name(Mode mode) {
    return render_mode_name({mode, StereoPass::kTwoPasses});
}

std::optional<StereoPass> parse_stereo_pass(const std::string& name) {
    return parse_name(kStereoPassNames, name);
}

std::string stereo_pass_name(StereoPass pass) {
    return name_of(kStereoPassNames, pass);
}

std::optional<RenderModeChoice> parse_render_mode(const std::string& name) {
    const auto named = parse_name(kRenderModeNames, name);
    if (!named) return std::nullopt;
    for (const ModeOfName& entry : kModesOfNames) {
        if (entry.named == *named) return entry.choice;
    }
    return std::nullopt;  // hybrid-auto: the study's, no renderer mode of its own
}

std::string render_mode_name(const RenderModeChoice& choice) {
    // A hybrid mode's stereo pass is not part of its name.
    const StereoPass pass =
        choice.mode == Mode::kStereo ? choice.stereo_pass : StereoPass::kTwoPasses;
    for (const ModeOfName& entry : kModesOfNames) {
        if (entry.choice.mode == choice.mode && entry.choice.stereo_pass == pass)
            return name_of(kRenderModeNames, entry.named);
    }
    return "?";
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
    const auto named = parse_name(kAntiAliasingNames, name);
    if (!named) return std::nullopt;
    return static_cast<AntiAliasing>(*named);  // the same values (render_choices.h)
}

std::string anti_aliasing_name(AntiAliasing aa) {
    return name_of(kAntiAliasingNames, static_cast<NamedAntiAliasing>(aa));
}

}  // namespace monoplane::plan
