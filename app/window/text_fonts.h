// The protocol's text in the experimenter window and the launcher (pages, questionnaire items,
// variables' help) in the participant's language: Dear ImGui's built-in font draws printable
// ASCII and Latin-1 only, so fonts with the rest are merged into its atlas (docs/protocols.md,
// "Languages").
#pragma once

#include <imgui.h>

namespace monoplane::window {

// Merges into `atlas`, after the font it has, at `pixels` high: DejaVu Sans (fonts-dejavu-core)
// for Latin Extended, Greek, Cyrillic and punctuation, and the first installed CJK font
// (fonts-wqy-microhei, fonts-noto-cjk, fonts-droid-fallback) for kana, full-width forms and the
// common ideographs of simplified Chinese and Japanese. Characters the first font has keep its
// look, so the window's ASCII text is unchanged. A font that is not installed is left out. Call
// before the atlas is built (the backend's font upload).
void merge_text_fonts(ImFontAtlas& atlas, float pixels);

}  // namespace monoplane::window
