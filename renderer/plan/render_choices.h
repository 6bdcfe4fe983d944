// The choices that shape a frame, as the CLI, protocols and bench.json name them: the mode, how
// the eyes' forward passes are drawn, hybrid's depth-based savings, anti-aliasing and the debug
// views. Vulkan-free, so the frame plan (frame_plan.h) and its tests need no GPU;
// renderer/modes/mode_renderer.h maps them onto passes.
#pragma once

#include <optional>
#include <string>

#include "common/render_mode_names.h"

namespace monoplane::plan {

enum class Mode { kStereo, kHybrid, kHybridFarfield };

// How the eyes' forward passes are drawn, in stereo and in hybrid's near region: one pass per eye,
// or one pass for both (papers/001's geometry-shader duplication, VK_KHR_multiview, or instancing:
// every draw's instance count doubled, the instance picking the eye) into the layers of two-layer
// targets. All four draw the same images (tests/gpu/single_pass_stereo_test).
enum class StereoPass { kTwoPasses, kMultiview, kGeometryShader, kInstanced };
// "two", "multiview", "gs", "instanced"
std::optional<StereoPass> parse_stereo_pass(const std::string& name);
std::string stereo_pass_name(StereoPass pass);

// A mode as the CLI, protocols and bench.json name it: stereo-multiview, stereo-gs and
// stereo-instanced are stereo with a single-pass StereoPass (docs/single-pass-stereo.md).
struct RenderModeChoice {
    Mode mode = Mode::kStereo;
    StereoPass stereo_pass = StereoPass::kTwoPasses;
};
// The names are common/render_mode_names.h's; "hybrid-auto" (the study's) is no choice here.
std::optional<RenderModeChoice> parse_render_mode(const std::string& name);
// "stereo", "stereo-multiview", "stereo-gs", "stereo-instanced", "hybrid", "hybrid-farfield"
// (the hybrid modes' stereo pass is not part of their name).
std::string render_mode_name(const RenderModeChoice& choice);

// Debug views of the hybrid modes.
// kRouting (any mode) colours each chunk by the lists the GPU culling put it in: green eyes
// only, blue C only, magenta both (papers/003's tool for choosing force-mono objects).
enum class DebugView { kNone, kTintMono, kStereoOnly, kMonoOnly, kRouting };

std::optional<Mode> parse_mode(const std::string& name);
std::string mode_name(Mode mode);
std::optional<DebugView> parse_debug_view(const std::string& name);

// How much of C's work the merged depth pyramid of both eyes saves (papers/000 Sect. 4.4 and the
// three variants of Sect. 5.1, Fig. 5): none ("No Opt.", frustum culling only), C's fragments
// hidden in both eyes rejected ("Discard"), and C's chunks hidden in both eyes not drawn at all
// ("Occl. Cull.", with Discard). hybrid-farfield uses frustum culling only. kAuto: the renderer
// measures the three on the frames it renders and uses the fastest (variant_chooser.h).
enum class MonoCulling { kNoOpt, kDiscard, kOcclusionCull, kAuto };
std::optional<MonoCulling> parse_mono_culling(const std::string& name);
// "no-opt", "discard", "occlusion-cull", "auto"
std::string mono_culling_name(MonoCulling culling);

// Anti-aliasing (papers/000 Sect. 4.5). TAA works in every mode; MSAA only in stereo, because
// resolving before the composite leaves C's samples out and resolving after it would need every
// sample mapped (docs/hybrid.md, "MSAA: stereo only, and why").
// The values are the named ones' (common/render_mode_names.h), whose table holds the names.
enum class AntiAliasing {
    kNone = static_cast<int>(NamedAntiAliasing::None),
    kTaa = static_cast<int>(NamedAntiAliasing::Taa),
    kMsaa2 = static_cast<int>(NamedAntiAliasing::Msaa2),
    kMsaa4 = static_cast<int>(NamedAntiAliasing::Msaa4),
    kMsaa8 = static_cast<int>(NamedAntiAliasing::Msaa8),
};
std::optional<AntiAliasing> parse_anti_aliasing(const std::string& name);  // "none", "taa", "msaa4"
std::string anti_aliasing_name(AntiAliasing aa);

}  // namespace monoplane::plan
