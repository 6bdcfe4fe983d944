#include "text/font.h"

#include <unordered_map>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include FT_ADVANCES_H
#include FT_TRUETYPE_TABLES_H

namespace monoplane::text {

struct Font::State {
    std::filesystem::path path;
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    FontMetrics metrics;
    mutable std::recursive_mutex mutex;
    mutable std::unordered_map<char32_t, double> advances;

    ~State() {
        if (face != nullptr) FT_Done_Face(face);
        if (library != nullptr) FT_Done_FreeType(library);
    }
};

namespace {

// The top of 'H''s outline in font units, or the OS/2 table's cap height for a font without
// one; 0 when neither is known.
double cap_height_units(FT_Face face) {
    const FT_UInt h = FT_Get_Char_Index(face, 'H');
    if (h != 0 && FT_Load_Glyph(face, h, FT_LOAD_NO_SCALE) == 0 &&
        face->glyph->format == FT_GLYPH_FORMAT_OUTLINE) {
        FT_BBox box;
        FT_Outline_Get_CBox(&face->glyph->outline, &box);
        if (box.yMax > 0) return static_cast<double>(box.yMax);
    }
    const auto* os2 = static_cast<const TT_OS2*>(FT_Get_Sfnt_Table(face, FT_SFNT_OS2));
    if (os2 != nullptr && os2->version >= 2 && os2->sCapHeight > 0) return os2->sCapHeight;
    return 0.0;
}

FontMetrics read_metrics(FT_Face face) {
    const double em = face->units_per_EM;
    FontMetrics m;
    m.ascender = face->ascender / em;
    m.descender = face->descender / em;
    m.line_spacing = face->height / em;
    const double cap = cap_height_units(face);
    // A font with neither (a symbol font): three quarters of the ascender, a typical cap height.
    m.cap_height = cap > 0.0 ? cap / em : 0.75 * m.ascender;
    return m;
}

}  // namespace

Font::Font(std::unique_ptr<State> state) : state_(std::move(state)) {}
Font::Font(Font&&) noexcept = default;
Font& Font::operator=(Font&&) noexcept = default;
Font::~Font() = default;

Result<Font> Font::open(const std::filesystem::path& path) {
    auto state = std::make_unique<State>();
    state->path = path;
    if (FT_Init_FreeType(&state->library) != 0) return Error{"FreeType could not start"};
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return Error{"no font file '" + path.string() + "'"};
    if (FT_New_Face(state->library, path.c_str(), 0, &state->face) != 0)
        return Error{"'" + path.string() +
                     "' is not a font FreeType can read (TrueType or "
                     "OpenType, .ttf/.otf/.ttc)"};
    if (!FT_IS_SCALABLE(state->face) || state->face->units_per_EM == 0)
        return Error{"'" + path.string() + "' is a bitmap font; give a scalable one (.ttf/.otf)"};
    if (FT_Select_Charmap(state->face, FT_ENCODING_UNICODE) != 0)
        return Error{"'" + path.string() + "' has no Unicode character map"};
    state->metrics = read_metrics(state->face);
    return Font(std::move(state));
}

const std::filesystem::path& Font::path() const {
    return state_->path;
}

std::string Font::name() const {
    const FT_Face f = state_->face;
    std::string name = f->family_name != nullptr ? f->family_name : "?";
    if (f->style_name != nullptr) name += std::string(" ") + f->style_name;
    return name;
}

bool Font::has_glyph(char32_t code_point) const {
    const std::lock_guard guard(state_->mutex);
    return FT_Get_Char_Index(state_->face, code_point) != 0;
}

double Font::advance(char32_t code_point) const {
    const std::lock_guard guard(state_->mutex);
    if (const auto found = state_->advances.find(code_point); found != state_->advances.end())
        return found->second;
    const FT_UInt glyph = FT_Get_Char_Index(state_->face, code_point);
    FT_Fixed units = 0;
    FT_Get_Advance(state_->face, glyph, FT_LOAD_NO_SCALE, &units);
    const double ems = static_cast<double>(units) / state_->face->units_per_EM;
    state_->advances.emplace(code_point, ems);
    return ems;
}

const FontMetrics& Font::metrics() const {
    return state_->metrics;
}

FT_FaceRec_* Font::face() const {
    return state_->face;
}

std::unique_lock<std::recursive_mutex> Font::lock() const {
    return std::unique_lock(state_->mutex);
}

}  // namespace monoplane::text
