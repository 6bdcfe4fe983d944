// A study condition: what one alternative of a trial shows — a scene,
// a render mode and the mono-plane distance. Plain data, so the study stays free of the
// renderer; the app translates a condition into scene generation and a render mode.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "common/result.h"
#include "study/render_mode.h"

namespace monoplane::study {

struct Condition {
    std::string scene;  // one of study_scene_names(), or a glTF file (names_scene_file())
    RenderMode mode = RenderMode::Stereo;
    // Metres in front of the eyes. It identifies the trial's distance even for modes that ignore
    // it (stereo), so both alternatives of a trial carry the same value.
    double mono_plane = 0.0;
};

// The built-in scenes a study may name (docs/scenes.md): "beams", "landscape", "spheres".
// It may name glTF files too (study/scene_files.h).
std::span<const std::string_view> study_scene_names();

// "spheres / hybrid / m = 8 m": for logs and error messages.
std::string describe(const Condition& condition);

// Checks a condition against the clip range it will be rendered with (default 0.1 and 1000 m):
// the scene is known or names a glTF file (whether the file exists is the protocol's check), and
// the mono plane is finite and strictly inside (near, far) — at or beyond either end hybrid
// rendering degenerates (docs/hybrid.md). Returns the condition unchanged when valid. May
// be called at any time; near and far are checked too (finite, 0 < near < far).
Result<Condition> validate_condition(const Condition& condition, double near, double far);

}  // namespace monoplane::study
