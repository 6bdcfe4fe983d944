#include "study/protocol_font.h"

#include <algorithm>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "common/toml/toml_problems.h"
#include "text/complex_scripts.h"
#include "text/font_cache.h"
#include "text/utf8.h"

namespace monoplane::study {
namespace {

// A string of the protocol shown in the headset, and where its value starts in the file.
struct ShownText {
    std::string key;
    std::string text;
    toml::source_region where;
};

void add_string(const toml::node* node, const std::string& key, std::vector<ShownText>& out) {
    if (node == nullptr) return;
    if (const auto* value = node->as_string()) out.push_back({key, value->get(), node->source()});
}

std::vector<ShownText> shown_texts(const toml::table& root) {
    std::vector<ShownText> out;
    if (const toml::array* pages = root["instructions"].as_array()) {
        for (const toml::node& page : *pages) {
            if (const toml::table* table = page.as_table())
                add_string(table->get("text"), "instructions.text", out);
        }
    }
    for (const char* table : {"ready", "breaks", "end"})
        add_string(root.at_path(std::string(table) + ".text").node(), std::string(table) + ".text",
                   out);
    if (const toml::array* items = root.at_path("questionnaire.items").as_array()) {
        for (const toml::node& item : *items) add_string(&item, "questionnaire.items", out);
    }
    for (const PromptKey& key : prompt_keys()) {
        const std::string path = "text.prompts." + std::string(key.key);
        add_string(root.at_path(path).node(), path, out);
    }
    return out;
}

// The characters of `text` that `font` lacks, each once, line breaks aside.
std::string missing_characters(std::string_view text, const text::Font& font) {
    std::u32string missing;
    for (const char32_t c : text::decode_utf8_lenient(text)) {
        if (c == U'\n' || missing.find(c) != std::u32string::npos) continue;
        if (!font.has_glyph(c)) missing += c;
    }
    return text::encode_utf8(missing);
}

// Where `character` is first written in the file at or after the value's start: the line and
// column an editor jumps to (the value's start for a character written as an escape).
toml::source_region located(std::string_view file, const toml::source_region& value,
                            std::string_view character) {
    std::size_t offset = 0;
    for (toml::source_index line = 1; line < value.begin.line && offset != std::string::npos;
         ++line)
        offset = file.find('\n', offset) + 1;
    if (offset == std::string::npos) return value;
    const std::size_t found = file.find(character, offset);
    if (found == std::string_view::npos) return value;
    toml::source_region where = value;
    where.begin.line = static_cast<toml::source_index>(
        value.begin.line + std::count(file.begin() + offset, file.begin() + found, '\n'));
    const std::size_t line_start = file.rfind('\n', found);
    const std::string_view before =
        file.substr(line_start == std::string::npos ? 0 : line_start + 1,
                    found - (line_start == std::string::npos ? 0 : line_start + 1));
    where.begin.column =
        static_cast<toml::source_index>(1 + text::decode_utf8_lenient(before).size());
    return where;
}

std::string font_words(const text::Font& font) {
    return "the font '" + font.name() + "' (" + font.path().string() + ", [text] font)";
}

void check_text(const ShownText& shown, const text::Font& font, std::string_view file,
                TomlProblems& problems) {
    std::u32string reported;
    for (const char32_t c : text::decode_utf8_lenient(shown.text)) {
        if (c == U'\n' || c == U'\r' || c == U'\t' || reported.find(c) != std::u32string::npos)
            continue;
        const std::string character = text::encode_utf8(c);
        const std::string named = "'" + character + "' (" + text::code_point_label(c) + ")";
        if (const std::optional<std::string> reason = text::needs_shaping(c)) {
            reported += c;
            problems.add(located(file, shown.where, character),
                         toml_key_prefix(shown.key) + named + " is " + *reason +
                             "; the headset draws one glyph per character, left to right");
        } else if (!font.has_glyph(c)) {
            reported += c;
            problems.add(located(file, shown.where, character),
                         toml_key_prefix(shown.key) + named + " is not in " + font_words(font) +
                             "; choose a font that has it (docs/protocols.md, \"Languages\")");
        }
    }
}

// The prompts the protocol leaves in English (those it gives were checked where written), and
// what the headset fills into them: digits and the countdown's colon.
void check_prompts(const HeadsetPrompts& prompts, const text::Font& font, TomlProblems& problems) {
    const HeadsetPrompts english;
    for (const PromptKey& key : prompt_keys()) {
        const std::string& prompt = prompts.*key.member;
        if (prompt != english.*key.member) continue;
        const std::string missing = missing_characters(prompt, font);
        if (missing.empty()) continue;
        problems.add("[text] font: " + font_words(font) + " lacks '" + missing +
                     "', which the headset's prompt '" + std::string(key.key) + "' uses (\"" +
                     prompt + "\"); give [text.prompts] " + std::string(key.key) +
                     " in the protocol's language, or choose a font that has them");
    }
    if (const std::string missing = missing_characters(kFilledCharacters, font); !missing.empty()) {
        problems.add("[text] font: " + font_words(font) + " lacks '" + missing +
                     "', which the headset's page numbers and countdowns use; choose a font "
                     "with digits");
    }
}

}  // namespace

Result<void> check_protocol_font(const Protocol& protocol) {
    Result<std::shared_ptr<const text::Font>> font = text::cached_font(protocol.day.font);
    if (!font.ok()) {
        return Error{protocol.source + ": [text] font: " + font.error().message +
                     " (docs/protocols.md, \"Languages\")"};
    }
    Result<toml::table> root = parse_toml(protocol.text, protocol.source);
    MONOPLANE_TRY(root);
    TomlProblems problems(protocol.source);
    for (const ShownText& shown : shown_texts(root.value()))
        check_text(shown, *font.value(), protocol.text, problems);
    check_prompts(protocol.day.prompts, *font.value(), problems);
    if (!problems.empty()) return problems.error();
    return Ok{};
}

}  // namespace monoplane::study
