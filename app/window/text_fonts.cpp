#include "app/window/text_fonts.h"

#include <array>
#include <filesystem>

#include "text/font.h"

namespace monoplane::window {
namespace {

// Unicode blocks beyond Latin-1 that European protocols write, as Dear ImGui's range pairs
// (first, last, ..., 0). The arrays must outlive the atlas's build: static.
constexpr std::array<ImWchar, 17> kEuropean = {
    0x0100, 0x024F,  // Latin Extended-A and -B (Polish, Czech, Turkish, Romanian, ...)
    0x0370, 0x03FF,  // Greek
    0x0400, 0x052F,  // Cyrillic and its supplement
    0x1E00, 0x1EFF,  // Latin Extended Additional (Vietnamese)
    0x2000, 0x206F,  // general punctuation: dashes, quotes, ellipsis
    0x20A0, 0x20BF,  // currency signs
    0x2190, 0x21FF,  // arrows
    0x2212, 0x2212,  // minus sign
    0};

// Debian's CJK fonts, lightest first: the first installed one is merged.
constexpr std::array<const char*, 3> kCjkFonts = {
    "/usr/share/fonts/truetype/wqy/wqy-microhei.ttc",
    "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc",
    "/usr/share/fonts/truetype/droid/DroidSansFallbackFull.ttf"};

void merge(ImFontAtlas& atlas, const char* path, float pixels, const ImWchar* ranges) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return;
    ImFontConfig config;
    config.MergeMode = true;
    // Thousands of ideographs: no horizontal oversampling keeps the atlas a few MB.
    config.OversampleH = 1;
    config.OversampleV = 1;
    config.PixelSnapH = true;
    atlas.AddFontFromFileTTF(path, pixels, &config, ranges);
}

}  // namespace

void merge_text_fonts(ImFontAtlas& atlas, float pixels) {
    merge(atlas, text::kDefaultFontPath, pixels, kEuropean.data());
    for (const char* path : kCjkFonts) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec)) continue;
        merge(atlas, path, pixels, atlas.GetGlyphRangesChineseSimplifiedCommon());
        merge(atlas, path, pixels, atlas.GetGlyphRangesJapanese());
        return;
    }
}

}  // namespace monoplane::window
