// A study day in the protocol (docs/protocols.md, "A study day"): sessions, repetitions,
// blocking, the participant's screens and the participant variables are read with their values,
// default to one plain session when absent, and every mistake in them is refused before a session
// starts with the file, the line, the key and, for a misspelling, the word that was meant.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "study/headset_prompts.h"
#include "study/protocol.h"

namespace monoplane::study {
namespace {

// Every study-day key, none at its default. Line numbers matter: the cases below expect them.
constexpr std::string_view kDayProtocol = R"(name = "day"
scenes = ["beams", "landscape", "spheres"]
mono_planes = [3, 8]
alternatives = ["stereo", "hybrid"]
sessions = 2
repetitions = 3
blocking = "scene"
text_height_deg = 1.5

[[instructions]]
text = "Page one."

[[instructions]]
text = """Page two,
on two lines."""

[ready]
text = "Practice is over. Press CONFIRM to begin."

[breaks]
every_trials = 6
between_blocks = true
min_s = 45
text = "Rest."

[end]
text = "Thank you."

[[variables]]
name = "age"
type = "integer"
min = 18
max = 99
required = true
help = "Age in years"

[[variables]]
name = "vision"
type = "choice"
choices = ["normal", "corrected", "other"]

[[variables]]
name = "ipd_mm"
type = "number"
min = 50.5

[[variables]]
name = "remark"
type = "text"
)";

// A staircase protocol (no study-day keys) that the staircase cases add to.
constexpr std::string_view kStaircaseProtocol = R"(name = "stairs"
scenes = ["beams", "spheres"]
mono_planes = [2, 4, 8, 16]
alternatives = ["stereo", "hybrid"]
procedure = "staircase"
[staircase]
rule = "weighted-up-down"
trials_per_scene = 30
)";

std::string replaced(std::string_view text, std::string_view from, std::string_view to) {
    std::string result(text);
    const std::size_t at = result.find(from);
    EXPECT_NE(at, std::string::npos) << "mutation target not found: " << from;
    EXPECT_EQ(result.find(from, at + 1), std::string::npos) << "not unique: " << from;
    if (at != std::string::npos) result.replace(at, from.size(), to);
    return result;
}

std::filesystem::path source_dir() {
    const char* dir = std::getenv("MONOPLANE_SOURCE_DIR");  // set by ctest
    return dir == nullptr ? std::filesystem::path{} : std::filesystem::path(dir);
}

TEST(StudyDayProtocol, EveryKeyIsReadWithItsValue) {
    const Result<Protocol> p = parse_protocol(kDayProtocol, "day.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    const StudyDaySettings& day = p->day;
    EXPECT_EQ(day.sessions, 2);
    EXPECT_EQ(day.repetitions, 3);
    EXPECT_EQ(day.blocking, Blocking::Scene);
    EXPECT_EQ(day.text_height_deg, 1.5);
    EXPECT_EQ(day.instructions,
              (std::vector<ScreenPage>{{"Page one."}, {"Page two,\non two lines."}}));
    EXPECT_EQ(day.ready, ScreenPage{"Practice is over. Press CONFIRM to begin."});
    EXPECT_EQ(day.breaks, (BreakSettings{6, true, 45.0, "Rest."}));
    EXPECT_EQ(day.end, ScreenPage{"Thank you."});
    EXPECT_TRUE(day.has_screens());
    // 3 scenes x 2 distances x 3 repetitions.
    EXPECT_EQ(p->trials_per_session(), 18u);

    ASSERT_EQ(day.variables.size(), 4u);
    EXPECT_EQ(
        day.variables[0],
        (ParticipantVariable{"age", VariableType::Integer, 18.0, 99.0, {}, true, "Age in years"}));
    EXPECT_EQ(day.variables[1], (ParticipantVariable{"vision",
                                                     VariableType::Choice,
                                                     std::nullopt,
                                                     std::nullopt,
                                                     {"normal", "corrected", "other"},
                                                     false,
                                                     ""}));
    EXPECT_EQ(
        day.variables[2],
        (ParticipantVariable{"ipd_mm", VariableType::Number, 50.5, std::nullopt, {}, false, ""}));
    EXPECT_EQ(day.variables[3].name, "remark");
    EXPECT_EQ(day.variables[3].type, VariableType::Text);
    EXPECT_FALSE(day.variables[3].min || day.variables[3].max || day.variables[3].required);
    EXPECT_TRUE(day.variables[3].choices.empty() && day.variables[3].help.empty());
}

TEST(StudyDayProtocol, AbsentKeysGiveOnePlainSession) {
    const Result<Protocol> p = parse_protocol(R"(name = "plain"
scenes = ["beams"]
mono_planes = [3, 8]
alternatives = ["stereo", "hybrid"]
)",
                                              "plain.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    const StudyDaySettings& day = p->day;
    EXPECT_EQ(day.sessions, 1);
    EXPECT_EQ(day.repetitions, 1);
    EXPECT_EQ(day.blocking, Blocking::Scene);
    EXPECT_EQ(day.text_height_deg, 1.0);
    EXPECT_TRUE(day.instructions.empty());
    EXPECT_FALSE(day.ready);
    EXPECT_FALSE(day.breaks);
    EXPECT_FALSE(day.end);
    EXPECT_TRUE(day.variables.empty());
    EXPECT_FALSE(day.has_screens());
    EXPECT_EQ(p->trials_per_session(), 2u);
}

// Pages in the participant's language: Latin with diacritics, Greek, Cyrillic and CJK parse
// (whether the font draws them is load_protocol's check, study_protocol_font_test).
TEST(StudyDayProtocol, PagesInOtherLanguagesAreAccepted) {
    for (const std::string page :
         {"Dr\u00fccken Sie SCHALTER, um zu wechseln. Gr\u00fc\u00dfe!",
          "\u03a0\u03b1\u03c4\u03ae\u03c3\u03c4\u03b5 "
          "\u0395\u039d\u0391\u039b\u039b\u0391\u0393\u0397",
          "\u041d\u0430\u0436\u043c\u0438\u0442\u0435 \u041f\u0415\u0420\u0415\u041a\u041b",
          "\u8bf7\u6309\u786e\u8ba4\u952e\u5f00\u59cb\u3002"}) {
        const Result<Protocol> p = parse_protocol(
            replaced(kDayProtocol, "text = \"Page one.\"", "text = \"" + page + "\""), "day.toml");
        ASSERT_TRUE(p.ok()) << p.error().message;
        EXPECT_EQ(p->day.instructions[0].text, page);
        EXPECT_EQ(p->day.font, "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");  // the default
    }
}

// Typographic punctuation and tabs: accepted, as written.
TEST(StudyDayProtocol, TypographicPunctuationIsAccepted) {
    const std::string page = "\u201cSWITCH\u201d \u2013 compare\u2026\tthen CONFIRM";
    const Result<Protocol> p = parse_protocol(
        replaced(kDayProtocol, "text = \"Page one.\"", "text = \"" + page + "\""), "day.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->day.instructions[0].text,
              "\xe2\x80\x9cSWITCH\xe2\x80\x9d \xe2\x80\x93 compare\xe2\x80\xa6\tthen CONFIRM");
}

TEST(StudyDayProtocol, BreakDefaultsAndBlockingNone) {
    std::string text =
        replaced(kDayProtocol, "between_blocks = true\nmin_s = 45\ntext = \"Rest.\"\n", "");
    text = replaced(text, "blocking = \"scene\"", "blocking = \"none\"");
    const Result<Protocol> p = parse_protocol(text, "day.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->day.blocking, Blocking::None);
    ASSERT_TRUE(p->day.breaks);
    EXPECT_EQ(p->day.breaks->every_trials, 6);
    EXPECT_FALSE(p->day.breaks->between_blocks);
    EXPECT_EQ(p->day.breaks->min_s, 30.0);
    EXPECT_EQ(p->day.breaks->text, "Take a short break. Remove the headset if you like.");
    // Between blocks alone, with no countdown.
    const Result<Protocol> blocks = parse_protocol(
        replaced(kDayProtocol, "every_trials = 6\nbetween_blocks = true\nmin_s = 45\n",
                 "between_blocks = true\nmin_s = 0\n"),
        "day.toml");
    ASSERT_TRUE(blocks.ok()) << blocks.error().message;
    EXPECT_EQ(blocks->day.breaks, (BreakSettings{0, true, 0.0, "Rest."}));
}

TEST(StudyDayProtocol, StaircasesTakeBreaksByCountButNoRepetitionsOrBlocks) {
    const std::string with_breaks = std::string(kStaircaseProtocol) +
                                    "repetitions = 1\n[breaks]\nevery_trials = 20\nmin_s = 60\n";
    // `repetitions = 1` is a root key only before the first table: move it up.
    const std::string ok =
        replaced(replaced(with_breaks, "repetitions = 1\n", ""), "procedure = \"staircase\"\n",
                 "procedure = \"staircase\"\nrepetitions = 1\n");
    const Result<Protocol> p = parse_protocol(ok, "stairs.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->day.breaks, (BreakSettings{20, false, 60.0, BreakSettings{}.text}));
    EXPECT_EQ(p->trials_per_session(), 60u);

    const Result<Protocol> repeated =
        parse_protocol(replaced(kStaircaseProtocol, "procedure = \"staircase\"\n",
                                "procedure = \"staircase\"\nrepetitions = 2\n"),
                       "stairs.toml");
    ASSERT_FALSE(repeated.ok());
    EXPECT_EQ(repeated.error().message,
              "stairs.toml:6:15: key 'repetitions': staircases choose their own trials (each "
              "scene's up to staircase.trials_per_scene); repetitions applies to procedure = "
              "'constant'");

    const Result<Protocol> blocked =
        parse_protocol(replaced(kStaircaseProtocol, "procedure = \"staircase\"\n",
                                "procedure = \"staircase\"\nblocking = \"none\"\n"),
                       "stairs.toml");
    ASSERT_FALSE(blocked.ok());
    EXPECT_NE(blocked.error().message.find("stairs.toml:6:12: key 'blocking': staircases "
                                           "interleave"),
              std::string::npos)
        << blocked.error().message;

    const Result<Protocol> between = parse_protocol(
        std::string(kStaircaseProtocol) + "[breaks]\nbetween_blocks = true\n", "stairs.toml");
    ASSERT_FALSE(between.ok());
    EXPECT_NE(between.error().message.find("stairs.toml:10:18: key 'breaks.between_blocks': a "
                                           "staircase session has no scene blocks"),
              std::string::npos)
        << between.error().message;
}

TEST(StudyDayProtocol, AllProblemsOfTheDayAreReportedAtOnceInOrder) {
    std::string text = replaced(kDayProtocol, "sessions = 2", "sessions = 0");
    text = replaced(text, "min_s = 45", "min_s = 3600");
    text = replaced(text, "type = \"choice\"", "type = \"choise\"");
    const Result<Protocol> p = parse_protocol(text, "day.toml");
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().message,
              "day.toml:5:12: key 'sessions': 0 is outside the allowed range 1..20\n"
              "day.toml:23:9: key 'breaks.min_s': 3600 s: a break longer than 30 minutes is not a "
              "break (at most 1800; end the session instead)\n"
              "day.toml:39:8: key 'variables.type': unknown value 'choise' (allowed: integer, "
              "number, choice, text); did you mean 'choice'?");
}

TEST(StudyDayProtocol, ABreakThatNeverComesIsRefused) {
    // 3 scenes x 2 distances x 3 repetitions = 18 data trials: no 18th-trial break.
    const Result<Protocol> p =
        parse_protocol(replaced(kDayProtocol, "every_trials = 6", "every_trials = 18"), "d.toml");
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().message,
              "d.toml:21:16: key 'breaks.every_trials': 18, but a session has 18 data trials, so "
              "this break would never be shown; use a smaller number");
    EXPECT_TRUE(
        parse_protocol(replaced(kDayProtocol, "every_trials = 6", "every_trials = 17"), "d.toml")
            .ok());
}

struct DayCase {
    std::string_view what;
    std::string_view from;
    std::string_view to;
    // Each must occur in the message: the place ("day.toml:5:") and the key matter most.
    std::vector<std::string_view> expected;
};

class MalformedDay : public testing::TestWithParam<DayCase> {};

TEST_P(MalformedDay, IsRefusedNamingSourceLineAndKey) {
    const DayCase& c = GetParam();
    const Result<Protocol> p = parse_protocol(replaced(kDayProtocol, c.from, c.to), "day.toml");
    ASSERT_FALSE(p.ok()) << c.what;
    const std::string& message = p.error().message;
    EXPECT_EQ(message.rfind("day.toml", 0), 0u) << message;
    for (std::string_view expected : c.expected) {
        EXPECT_NE(message.find(expected), std::string::npos)
            << c.what << ": expected \"" << expected << "\" in:\n"
            << message;
    }
}

const std::string kLongPage = "text = \"" + std::string(2001, 'a') + "\"";

const DayCase kDayCases[] = {
    // The top-level keys.
    {"too many sessions",
     "sessions = 2",
     "sessions = 21",
     {"day.toml:5:12: key 'sessions': 21 is outside the allowed range 1..20"}},
    {"sessions as text",
     "sessions = 2",
     "sessions = \"2\"",
     {"day.toml:5:", "'sessions'", "an integer in 1..20", "but is a string"}},
    {"no repetitions",
     "repetitions = 3",
     "repetitions = 0",
     {"day.toml:6:", "'repetitions'", "outside the allowed range 1..50"}},
    {"too many repetitions", "repetitions = 3", "repetitions = 51", {"day.toml:6:", "1..50"}},
    {"misspelt repetitions",
     "repetitions = 3",
     "repetition = 3",
     {"day.toml:6:1: key 'repetition': unknown key (did you mean 'repetitions'?)"}},
    {"misspelt blocking value",
     "blocking = \"scene\"",
     "blocking = \"scenes\"",
     {"day.toml:7:12: key 'blocking': unknown value 'scenes' (allowed: scene, none); did you "
      "mean 'scene'?"}},
    {"blocking as a number",
     "blocking = \"scene\"",
     "blocking = 1",
     {"day.toml:7:", "'blocking'", "one of scene, none", "integer"}},
    {"tiny text",
     "text_height_deg = 1.5",
     "text_height_deg = 0.2",
     {"day.toml:8:19: key 'text_height_deg': 0.2 degrees is outside from 0.5 to 10"}},
    {"huge text", "text_height_deg = 1.5", "text_height_deg = 12", {"day.toml:8:", "0.5 to 10"}},
    {"text height as text",
     "text_height_deg = 1.5",
     "text_height_deg = \"1\"",
     {"day.toml:8:", "'text_height_deg'", "degrees of visual angle", "string"}},
    // [[instructions]]
    {"misspelt instructions table",
     "[[instructions]]\ntext = \"Page one.\"",
     "[[instruction]]\ntext = \"Page one.\"",
     {"day.toml:10:3: key 'instruction': unknown key (did you mean 'instructions'?)"}},
    {"misspelt text key",
     "text = \"Page one.\"",
     "txt = \"Page one.\"",
     {"day.toml:11:1: key 'instructions.txt': unknown key (did you mean 'instructions.text'?)",
      "day.toml:10:1: key 'instructions.text': required key is missing"}},
    {"blank page",
     "text = \"Page one.\"",
     "text = \"  \"",
     {"day.toml:11:8: key 'instructions.text': is empty"}},
    {"page too long",
     "text = \"Page one.\"",
     kLongPage,
     {"day.toml:11:", "'instructions.text'", "2001 characters", "at most 2000"}},
    {"page in Hebrew",
     "text = \"Page one.\"",
     "text = \"Press \u05e9\u05dc\u05d5\u05dd\"",
     {"day.toml:11:8: key 'instructions.text': character 7 ('\xd7\xa9' U+05E9, after 'Press ') "
      "cannot be shown in the headset: it is Hebrew script, which needs shaping and "
      "right-to-left layout; the headset draws one glyph per character, left to right"}},
    {"page in Devanagari",
     "text = \"Page one.\"",
     "text = \"\u0928\u092e\u0938\u094d\u0924\u0947\"",
     {"day.toml:11:8: key 'instructions.text': character 1 ('\xe0\xa4\xa8' U+0928, after '') "
      "cannot be shown in the headset: it is Devanagari script, which needs shaping (letters "
      "change form and order)"}},
    {"page with a combining mark",
     "text = \"Page one.\"",
     "text = \"Caf\u0065\u0301\"",
     {"day.toml:11:8:", "character 5 ('\xcc\x81' U+0301, after 'Cafe')",
      "a combining mark: write the precomposed letter instead"}},
    {"text font not a string",
     "text_height_deg = 1.5",
     "text_height_deg = 1.5\n[text]\nfont = 3",
     {"'text.font'", "the path of a TrueType or OpenType font file", "integer"}},
    {"text font empty",
     "text_height_deg = 1.5",
     "text_height_deg = 1.5\n[text]\nfont = \"\"",
     {"key 'text.font': is empty; give the path of a font file"}},
    {"text with an unknown key",
     "text_height_deg = 1.5",
     "text_height_deg = 1.5\n[text]\nfonts = \"a.ttf\"",
     {"key 'text.fonts': unknown key (did you mean 'text.font'?)"}},
    {"page with a control character",
     "text = \"Page one.\"",
     "text = \"Page\\rone.\"",
     {"day.toml:11:", "character 5 (a control character, after 'Page')"}},
    {"page as a number",
     "text = \"Page one.\"",
     "text = 1",
     {"day.toml:11:", "'instructions.text'", "a string", "integer"}},
    // [ready] and [end]
    {"ready without text",
     "text = \"Practice is over. Press CONFIRM to begin.\"",
     "words = \"Practice is over.\"",
     {"day.toml:18:1: key 'ready.words': unknown key (known keys in [ready]: text)",
      "day.toml:17:1: key 'ready.text': required key is missing"}},
    {"end as a key of [breaks]",
     "[end]\ntext = \"Thank you.\"",
     "end = \"Thank you.\"",
     {"day.toml:26:1: key 'breaks.end': unknown key (known keys in [breaks]: every_trials, "
      "between_blocks, min_s, text)"}},
    {"blank end", "text = \"Thank you.\"", "text = \"\"", {"day.toml:27:", "'end.text'", "empty"}},
    // [breaks]
    {"negative break",
     "min_s = 45",
     "min_s = -1",
     {"day.toml:23:9: key 'breaks.min_s': -1 is not a number of seconds >= 0"}},
    {"a break of an hour",
     "min_s = 45",
     "min_s = 3600",
     {"day.toml:23:", "a break longer than 30 minutes is not a break"}},
    {"break as text",
     "min_s = 45",
     "min_s = \"45 s\"",
     {"day.toml:23:", "'breaks.min_s'", "a number of seconds", "string"}},
    {"no trigger",
     "every_trials = 6\nbetween_blocks = true",
     "every_trials = 0\nbetween_blocks = false",
     {"day.toml:20:1: key 'breaks': shows no break: give every_trials = N (N > 0) or "
      "between_blocks = true, or remove [breaks]"}},
    {"too many trials between breaks",
     "every_trials = 6",
     "every_trials = 1001",
     {"day.toml:21:", "'breaks.every_trials'", "0..1000"}},
    {"between blocks as text",
     "between_blocks = true",
     "between_blocks = \"yes\"",
     {"day.toml:22:", "'breaks.between_blocks'", "boolean"}},
    {"between blocks without blocks",
     "blocking = \"scene\"",
     "blocking = \"none\"",
     {"day.toml:22:18: key 'breaks.between_blocks': blocking = 'none' puts every trial in one "
      "block"}},
    {"misspelt break key",
     "every_trials = 6",
     "every_trial = 6",
     {"day.toml:21:1: key 'breaks.every_trial': unknown key (did you mean "
      "'breaks.every_trials'?)"}},
    {"blank break text",
     "text = \"Rest.\"",
     "text = \" \"",
     {"day.toml:24:", "'breaks.text'", "empty"}},
    // [[variables]]
    {"capital name",
     "name = \"age\"",
     "name = \"Age\"",
     {"day.toml:30:8: key 'variables.name': 'Age' is not a variable name"}},
    {"long name",
     "name = \"age\"",
     "name = \"a_name_longer_than_thirty_two_chars\"",
     {"day.toml:30:", "at most 32 characters"}},
    {"duplicate name",
     "name = \"vision\"",
     "name = \"age\"",
     {"day.toml:38:8: key 'variables.name': variable 'age' is declared twice"}},
    {"missing name",
     "name = \"remark\"\n",
     "",
     {"day.toml:47:1: key 'variables.name': required key is missing"}},
    {"missing type",
     "type = \"text\"\n",
     "",
     {"day.toml:47:1: key 'variables.type': required key is missing (one of integer, number, "
      "choice, text)"}},
    {"shortened type",
     "type = \"integer\"",
     "type = \"int\"",
     {"day.toml:31:8: key 'variables.type': unknown value 'int'", "did you mean 'integer'?"}},
    {"fractional bound on an integer",
     "min = 18",
     "min = 18.5",
     {"day.toml:32:7: key 'variables.min': must be an integer (the variable is an integer), but "
      "is a floating-point number"}},
    {"min above max",
     "min = 18",
     "min = 100",
     {"day.toml:33:7: key 'variables.max': 99 is below min = 100"}},
    {"range on a choice",
     "choices = [\"normal\", \"corrected\", \"other\"]",
     "choices = [\"normal\", \"corrected\", \"other\"]\nmax = 3",
     {"day.toml:41:7: key 'variables.max': applies to integer and number variables, but "
      "'vision' is of type 'choice'"}},
    {"choices on a number",
     "min = 50.5",
     "choices = [\"50\"]",
     {"day.toml:45:11: key 'variables.choices': applies to choice variables, but 'ipd_mm' is of "
      "type 'number'"}},
    {"choice without choices",
     "choices = [\"normal\", \"corrected\", \"other\"]\n",
     "",
     {"day.toml:37:1: key 'variables.choices': required key is missing"}},
    {"no choices",
     "choices = [\"normal\", \"corrected\", \"other\"]",
     "choices = []",
     {"day.toml:40:", "'variables.choices': is empty"}},
    {"repeated choice",
     "choices = [\"normal\", \"corrected\", \"other\"]",
     "choices = [\"normal\", \"corrected\", \"normal\"]",
     {"day.toml:40:", "duplicate choice 'normal'"}},
    {"blank choice",
     "choices = [\"normal\", \"corrected\", \"other\"]",
     "choices = [\"normal\", \"\", \"other\"]",
     {"day.toml:40:", "a choice is empty"}},
    {"number choice",
     "choices = [\"normal\", \"corrected\", \"other\"]",
     "choices = [\"normal\", 2]",
     {"day.toml:40:", "'variables.choices element 2'", "a string", "integer"}},
    {"required as text",
     "required = true",
     "required = \"yes\"",
     {"day.toml:34:", "'variables.required'", "boolean"}},
    {"help of two lines",
     "help = \"Age in years\"",
     "help = \"Age\\nin years\"",
     {"day.toml:35:", "'variables.help'", "one line"}},
    {"misspelt variable key",
     "required = true",
     "requried = true",
     {"day.toml:34:1: key 'variables.requried': unknown key (did you mean "
      "'variables.required'?)"}},
};

INSTANTIATE_TEST_SUITE_P(Cases, MalformedDay, testing::ValuesIn(kDayCases),
                         [](const testing::TestParamInfo<DayCase>& info) {
                             std::string name;
                             for (const char c : info.param.what) {
                                 name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                             }
                             return name;
                         });

TEST(StudyDayProtocol, ListsGivenAsOtherThanArraysOfTablesAreRefused) {
    const std::string base(R"(name = "v"
scenes = ["beams"]
mono_planes = [3]
alternatives = ["stereo", "hybrid"]
)");
    const Result<Protocol> text = parse_protocol(base + "variables = \"age\"\n", "v.toml");
    ASSERT_FALSE(text.ok());
    EXPECT_EQ(text.error().message,
              "v.toml:5:13: key 'variables': must be an array of tables ([[variables]], each with "
              "name and type), but is a string");
    const Result<Protocol> table =
        parse_protocol(base + "[instructions]\ntext = \"x\"\n", "v.toml");
    ASSERT_FALSE(table.ok());
    EXPECT_EQ(table.error().message,
              "v.toml:5:1: key 'instructions': must be an array of tables ([[instructions]], each "
              "with text), but is a table");
    const Result<Protocol> end = parse_protocol(base + "end = \"Thanks\"\n", "v.toml");
    ASSERT_FALSE(end.ok());
    EXPECT_EQ(end.error().message,
              "v.toml:5:7: key 'end': must be a table ([end] with text), but is a string");
    const Result<Protocol> list = parse_protocol(base + "instructions = [\"Read me\"]\n", "v.toml");
    ASSERT_FALSE(list.ok());
    EXPECT_EQ(list.error().message,
              "v.toml:5:17: key 'instructions': page 1 must be a table ([[instructions]] with "
              "text), but is a string");
}

// The parser's own list of the keys a table knows, as its message for an unknown key gives it
// ("known keys in [breaks]: every_trials, ..."); `table` empty for the top level.
std::vector<std::string> known_keys(const std::string& text, const std::string& table) {
    const Result<Protocol> p = parse_protocol(text, "keys.toml");
    EXPECT_FALSE(p.ok());
    if (p.ok()) return {};
    const std::string intro = "(known keys" + (table.empty() ? "" : " in [" + table + "]") + ": ";
    const std::string& message = p.error().message;
    const std::size_t start = message.find(intro);
    EXPECT_NE(start, std::string::npos) << message;
    if (start == std::string::npos) return {};
    const std::size_t end = message.find(')', start);
    std::vector<std::string> keys;
    std::stringstream list(message.substr(start + intro.size(), end - start - intro.size()));
    for (std::string key; std::getline(list, key, ',');) keys.push_back(key.substr(key[0] == ' '));
    return keys;
}

// docs/protocols.md is the users' reference: every key the parser knows is in it.
TEST(StudyDayProtocol, TheReferenceDocumentsEveryKeyTheParserKnows) {
    if (source_dir().empty()) GTEST_SKIP() << "MONOPLANE_SOURCE_DIR not set (run through ctest)";
    std::ifstream file(source_dir() / "docs" / "protocols.md");
    ASSERT_TRUE(file) << "docs/protocols.md";
    const std::string doc{std::istreambuf_iterator<char>(file), {}};
    const std::string base =
        "name = \"k\"\nscenes = [\"beams\"]\nmono_planes = [3, 8]\nalternatives = [\"stereo\", "
        "\"hybrid-auto\"]\nprocedure = \"staircase\"\nzzzzzzzz = 1\n";
    const std::string junk = "\nzzzzzzzz = 1\n";
    const std::vector<std::pair<std::string, std::string>> tables = {
        {"", base},
        {"questionnaire", base + "[questionnaire]\nitems = [\"a\"]" + junk},
        {"render", base + "[render]" + junk},
        {"auto", base + "[auto]" + junk},
        {"staircase", base + "[staircase]\nrule = \"quest+\"\ntrials_per_scene = 5" + junk},
        {"instructions", base + "[[instructions]]\ntext = \"a\"" + junk},
        {"ready", base + "[ready]\ntext = \"a\"" + junk},
        {"breaks", base + "[breaks]\nevery_trials = 1" + junk},
        {"end", base + "[end]\ntext = \"a\"" + junk},
        {"variables", base + "[[variables]]\nname = \"a\"\ntype = \"text\"" + junk},
        {"text", base + "[text]" + junk},
        {"text.prompts", base + "[text.prompts]" + junk},
    };
    std::size_t count = 0;
    for (const auto& [table, text] : tables) {
        const std::vector<std::string> keys = known_keys(text, table);
        EXPECT_FALSE(keys.empty()) << table;
        for (const std::string& key : keys) {
            ++count;
            // A table of the top level is written as it is headed: `[render]`, `[[variables]]`.
            const bool found = doc.find("`" + key + "`") != std::string::npos ||
                               doc.find("`[" + key + "]`") != std::string::npos ||
                               doc.find("`[[" + key + "]]`") != std::string::npos;
            EXPECT_TRUE(found) << "docs/protocols.md does not describe "
                               << (table.empty() ? "" : table + ".") << key;
        }
    }
    EXPECT_GE(count, 50u);
}

// Every protocol the repository ships reads, and none requires a variable: the README and the
// tests run them without --var.
TEST(StudyDayProtocol, EveryShippedProtocolParses) {
    if (source_dir().empty()) GTEST_SKIP() << "MONOPLANE_SOURCE_DIR not set (run through ctest)";
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "protocols")) {
        if (entry.path().extension() != ".toml") continue;
        ++count;
        const Result<Protocol> p = load_protocol(entry.path());
        ASSERT_TRUE(p.ok()) << p.error().message;
        for (const ParticipantVariable& v : p->day.variables) {
            EXPECT_FALSE(v.required) << entry.path() << ": " << v.name;
        }
    }
    EXPECT_GE(count, 3);
}

// papers/000 Sect. 6.1: an introduction before the trials; switching freely, then confirming.
TEST(StudyDayProtocol, Fink2019ToldItsParticipantsWhatThePaperSays) {
    if (source_dir().empty()) GTEST_SKIP() << "MONOPLANE_SOURCE_DIR not set (run through ctest)";
    const Result<Protocol> p = load_protocol(source_dir() / "protocols" / "fink2019.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    const StudyDaySettings& day = p->day;
    ASSERT_GE(day.instructions.size(), 2u);
    std::string all;
    for (const ScreenPage& page : day.instructions) all += page.text + "\n";
    for (std::string_view word : {"SWITCH", "CONFIRM", "practice", "two versions"}) {
        EXPECT_NE(all.find(word), std::string::npos) << word << " in:\n" << all;
    }
    EXPECT_TRUE(day.ready);
    ASSERT_TRUE(day.breaks);
    EXPECT_TRUE(day.breaks->between_blocks);
    EXPECT_GE(day.breaks->min_s, 30.0);
    EXPECT_TRUE(day.end);
    EXPECT_EQ(day.repetitions, 1);  // the paper's 30 decisions
    EXPECT_EQ(p->trials_per_session(), 30u);
}

TEST(StudyDayProtocol, DemoShowsOneShortPageAndThresholdTakesBreaks) {
    if (source_dir().empty()) GTEST_SKIP() << "MONOPLANE_SOURCE_DIR not set (run through ctest)";
    const Result<Protocol> demo = load_protocol(source_dir() / "protocols" / "demo.toml");
    ASSERT_TRUE(demo.ok()) << demo.error().message;
    ASSERT_EQ(demo->day.instructions.size(), 1u);
    EXPECT_LE(demo->day.instructions[0].text.size(), 300u);
    EXPECT_EQ(demo->trials_per_session(), 6u);
    const Result<Protocol> threshold = load_protocol(source_dir() / "protocols" / "threshold.toml");
    ASSERT_TRUE(threshold.ok()) << threshold.error().message;
    ASSERT_TRUE(threshold->day.breaks);
    EXPECT_GT(threshold->day.breaks->every_trials, 0);
    EXPECT_LT(static_cast<std::size_t>(threshold->day.breaks->every_trials),
              threshold->trials_per_session());
}

// A prompt's placeholders filled in, and the problems a template can have.
TEST(HeadsetPrompts, PlaceholdersAreFilledAndCheckedPerPrompt) {
    const std::pair<std::string_view, std::string> values[] = {{"page", "2"}, {"pages", "3"}};
    EXPECT_EQ(fill_prompt("Seite {page} von {pages}", values), "Seite 2 von 3");
    EXPECT_EQ(fill_prompt("{pages}/{page}", values), "3/2");
    EXPECT_EQ(fill_prompt("\u7b2c{page}\u9875", values), "\u7b2c2\u9875");
    EXPECT_EQ(fill_prompt("no placeholder", values), "no placeholder");
    EXPECT_EQ(fill_prompt("{time} left", values), "{time} left");  // no value: as written
    EXPECT_EQ(fill_prompt("open { brace", values), "open { brace");

    const std::string_view page[] = {"page", "pages"};
    EXPECT_EQ(prompt_placeholder_problem("Seite {page} von {pages}", page), std::nullopt);
    EXPECT_EQ(prompt_placeholder_problem("Seite {seite}", page),
              "uses {seite}; this prompt knows {page}, {pages}");
    EXPECT_EQ(prompt_placeholder_problem("Seite {page", page),
              "has a '{' without its '}'; this prompt knows {page}, {pages}");
    EXPECT_EQ(prompt_placeholder_problem("Seite page}", page),
              "has a '}' without its '{'; this prompt knows {page}, {pages}");
    EXPECT_EQ(prompt_placeholder_problem("Weiter {page}", {}),
              "uses {page}; this prompt has no placeholders");
    // Every prompt is listed once, each with a default that uses only its own placeholders.
    const HeadsetPrompts english;
    std::set<std::string_view> keys;
    for (const PromptKey& key : prompt_keys()) {
        EXPECT_TRUE(keys.insert(key.key).second) << key.key;
        EXPECT_EQ(prompt_placeholder_problem(english.*key.member, key.placeholders), std::nullopt)
            << key.key;
    }
    EXPECT_EQ(keys.size(), 11u);
}

}  // namespace
}  // namespace monoplane::study
