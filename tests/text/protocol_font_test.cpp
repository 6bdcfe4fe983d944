// A protocol's [text] font checked against its pages when the file is loaded
// (study/protocol_font.h): only characters the chosen font cannot draw are refused, each named
// with its code point, file, line and column; scripts that need shaping are refused with that
// reason; the shipped German protocol and the Chinese fixture load.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "study/protocol.h"
#include "tests/text/freetype_reference.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

fs::path source_dir() {
    const char* dir = std::getenv("MONOPLANE_SOURCE_DIR");
    return dir != nullptr ? fs::path(dir) : fs::path(MONOPLANE_SOURCE_DIR_FALLBACK);
}

class ProtocolFont : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("monoplane-protocol-font-" + std::to_string(::getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path path = dir_ / name;
        std::ofstream(path) << text;
        return path;
    }

    fs::path dir_;
};

// Line numbers matter: the page's third line holds the ideograph.
const std::string kProtocol = R"(name = "font"
scenes = ["beams"]
mono_planes = [3, 8]
alternatives = ["stereo", "hybrid"]
practice_trials = 0
[[instructions]]
text = """Drücken Sie SWITCH.
Ελληνικά και кириллица.
Chinese: 中文。"""
)";

TEST_F(ProtocolFont, TheDefaultFontDrawsEuropeanScriptsAndNamesTheCharactersItLacks) {
    const fs::path file = write("p.toml", kProtocol);
    const Result<Protocol> p = load_protocol(file);
    ASSERT_FALSE(p.ok());
    const std::string font = "the font 'DejaVu Sans Book' (" + std::string(text::kDefaultFontPath) +
                             ", [text] font); choose a font that has it";
    // One problem per missing character, each where it is written: line 9, after "Chinese: ".
    EXPECT_EQ(p.error().message,
              file.string() + ":9:10: key 'instructions.text': '\u4e2d' (U+4E2D) is not in " +
                  font + " (docs/protocols.md, \"Languages\")\n" + file.string() +
                  ":9:11: key 'instructions.text': '\u6587' (U+6587) is not in " + font +
                  " (docs/protocols.md, \"Languages\")\n" + file.string() +
                  ":9:12: key 'instructions.text': '\u3002' (U+3002) is not in " + font +
                  " (docs/protocols.md, \"Languages\")");
    // Without the Chinese line, German, Greek and Cyrillic load.
    const Result<Protocol> european = load_protocol(
        write("e.toml", kProtocol.substr(0, kProtocol.find("\nChinese")) + "\"\"\"\n"));
    ASSERT_TRUE(european.ok()) << european.error().message;
    EXPECT_EQ(european->day.font, text::kDefaultFontPath);
}

TEST_F(ProtocolFont, ACjkFontDrawsTheChinesePage) {
    if (!fs::exists(testing::kWqyMicroHei)) GTEST_SKIP() << "fonts-wqy-microhei not installed";
    const std::string text = "[text]\nfont = \"" + std::string(testing::kWqyMicroHei) + "\"\n";
    const Result<Protocol> p = load_protocol(write("zh.toml", kProtocol + text));
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->day.font, testing::kWqyMicroHei);
    const Result<Protocol> fixture =
        load_protocol(source_dir() / "tests" / "fixtures" / "text" / "demo-zh.toml");
    ASSERT_TRUE(fixture.ok()) << fixture.error().message;
    EXPECT_NE(fixture->day.instructions.at(0).text.find("\u6bcf\u4e2a\u573a\u666f"),
              std::string::npos);
}

TEST_F(ProtocolFont, ARelativeFontIsRefusedAndAMissingOneIsNamed) {
    // A resumed session reads the stored protocol away from its folder: absolute paths only.
    const fs::path relative = write("rel.toml", kProtocol + "[text]\nfont = \"fonts/sans.ttf\"\n");
    const Result<Protocol> p = load_protocol(relative);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().message, relative.string() +
                                     ":11:8: key 'text.font': 'fonts/sans.ttf' is a relative path; "
                                     "give the font file's absolute path (fc-list lists them), so "
                                     "that a resumed session finds it too");
    const fs::path nowhere = dir_ / "nowhere.ttf";
    const fs::path file =
        write("missing.toml", kProtocol + "[text]\nfont = \"" + nowhere.string() + "\"\n");
    const Result<Protocol> missing = load_protocol(file);
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().message, file.string() + ": [text] font: no font file '" +
                                           nowhere.string() +
                                           "' (docs/protocols.md, \"Languages\")");
    // Not a font at all: the protocol itself.
    const fs::path self = dir_ / "self.toml";
    write("self.toml", kProtocol + "[text]\nfont = \"" + self.string() + "\"\n");
    const Result<Protocol> not_font = load_protocol(self);
    ASSERT_FALSE(not_font.ok());
    EXPECT_NE(not_font.error().message.find("is not a font FreeType can read"), std::string::npos)
        << not_font.error().message;
}

TEST_F(ProtocolFont, AQuestionnaireItemInArabicIsRefusedForShaping) {
    const fs::path file = write(
        "ar.toml",
        kProtocol.substr(0, kProtocol.find("\nChinese")) +
            "\"\"\"\n[questionnaire]\nitems = [\"OK\", \"\u0645\u0631\u062d\u0628\u0627\"]\n");
    const Result<Protocol> p = load_protocol(file);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().message.substr(0, p.error().message.find('\n')),
              file.string() +
                  ":10:17: key 'questionnaire.items': '\u0645' (U+0645) is Arabic "
                  "script, which needs shaping and right-to-left layout; the "
                  "headset draws one glyph per character, left to right");
}

// The headset's own words in the participant's language: each given prompt replaces the English
// one, an empty one is left out, the rest stay English; each is checked where it is written.
const std::string kGermanPrompts = R"([text.prompts]
page = "Seite {page} von {pages}"
next = "CONFIRM: weiter"
back = ""
break = "Pause: noch {time}"
)";

TEST_F(ProtocolFont, PromptsInTheParticipantsLanguage) {
    const std::string european = kProtocol.substr(0, kProtocol.find("\nChinese")) + "\"\"\"\n";
    const Result<Protocol> p = load_protocol(write("de.toml", european + kGermanPrompts));
    ASSERT_TRUE(p.ok()) << p.error().message;
    const HeadsetPrompts& prompts = p->day.prompts;
    EXPECT_EQ(prompts.page, "Seite {page} von {pages}");
    EXPECT_EQ(prompts.next, "CONFIRM: weiter");
    EXPECT_EQ(prompts.back, "");
    EXPECT_EQ(prompts.countdown, "Pause: noch {time}");
    EXPECT_EQ(prompts.begin, "Press CONFIRM to begin");  // not given: English
    EXPECT_EQ(prompts.paused, "Paused");
}

TEST_F(ProtocolFont, APromptIsCheckedWhereItIsWritten) {
    const std::string european = kProtocol.substr(0, kProtocol.find("\nChinese")) + "\"\"\"\n";
    // Line 9: [text.prompts]; 10: page, 11: next, 12: paused, 13: an unknown prompt.
    const fs::path file = write("bad.toml", european +
                                                "[text.prompts]\n"
                                                "page = \"Seite {seite}\"\n"
                                                "next = \"\u7ee7\u7eed\"\n"
                                                "paused = 3\n"
                                                "pause = \"Pause\"\n");
    const Result<Protocol> p = load_protocol(file);
    ASSERT_FALSE(p.ok());
    const std::string& m = p.error().message;
    EXPECT_NE(m.find(file.string() +
                     ":10:8: key 'text.prompts.page': uses {seite}; this prompt knows {page}, "
                     "{pages}"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find(file.string() + ":12:10: key 'text.prompts.paused': "), std::string::npos)
        << m;
    EXPECT_NE(m.find(file.string() + ":13:1: key 'text.prompts.pause': unknown key (did you mean "
                                     "'text.prompts.paused'?)"),
              std::string::npos)
        << m;
    // Parsed without those, the font is judged: the Chinese prompt's characters, at their column.
    const fs::path chinese =
        write("zh-prompt.toml", european + "[text.prompts]\nnext = \"\u7ee7\u7eed\"\n");
    const Result<Protocol> q = load_protocol(chinese);
    ASSERT_FALSE(q.ok());
    EXPECT_EQ(q.error().message.substr(0, q.error().message.find('\n')),
              chinese.string() +
                  ":10:9: key 'text.prompts.next': '\u7ee7' (U+7EE7) is not in the font "
                  "'DejaVu Sans Book' (" +
                  std::string(text::kDefaultFontPath) +
                  ", [text] font); choose a font that has it (docs/protocols.md, \"Languages\")");
}

TEST(ShippedProtocols, Fink2019InGermanHasFink2019sDesign) {
    const Result<Protocol> en = load_protocol(source_dir() / "protocols" / "fink2019.toml");
    const Result<Protocol> de = load_protocol(source_dir() / "protocols" / "fink2019-de.toml");
    ASSERT_TRUE(en.ok()) << en.error().message;
    ASSERT_TRUE(de.ok()) << de.error().message;
    EXPECT_EQ(de->scenes, en->scenes);
    EXPECT_EQ(de->mono_planes, en->mono_planes);
    EXPECT_EQ(de->alternatives, en->alternatives);
    EXPECT_EQ(de->practice_trials, en->practice_trials);
    EXPECT_EQ(de->render, en->render);
    EXPECT_EQ(de->day.instructions.size(), en->day.instructions.size());
    EXPECT_EQ(de->questionnaire.items.size(), en->questionnaire.items.size());
    ASSERT_TRUE(de->day.breaks && en->day.breaks);
    EXPECT_EQ(de->day.breaks->between_blocks, en->day.breaks->between_blocks);
    EXPECT_EQ(de->day.breaks->min_s, en->day.breaks->min_s);
    EXPECT_NE(de->day.instructions[1].text.find("Dr\u00fccken Sie SWITCH"), std::string::npos);
    EXPECT_NE(de->day.breaks->text.find("schlie\u00dfen"), std::string::npos);
    // The headset's own words are German too: no English reaches the participant.
    const HeadsetPrompts english;
    for (const PromptKey& key : prompt_keys()) {
        EXPECT_NE(de->day.prompts.*key.member, english.*key.member) << key.key;
        EXPECT_EQ(en->day.prompts.*key.member, english.*key.member) << key.key;
    }
    EXPECT_EQ(de->day.prompts.page, "Seite {page} von {pages}");
}

}  // namespace
}  // namespace monoplane::study
