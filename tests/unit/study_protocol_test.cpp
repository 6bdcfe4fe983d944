// Study protocols: the shipped files carry the paper's design (papers/000 Sect. 6), and every
// class of malformed protocol is refused before a session starts, with a message that names the
// file, the line and the key.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "study/protocol.h"

namespace monoplane::study {
namespace {

// A valid protocol that every malformed case below mutates in one place. Line numbers matter:
// the cases expect them.
constexpr std::string_view kValidProtocol = R"(name = "test"
scenes = ["beams", "landscape", "spheres"]
mono_planes = [1.6, 3, 8, 31, 39.5]
alternatives = ["stereo", "hybrid"]
order = "randomized"
first_scene = "latin-square"
require_both_viewed = true
practice_trials = 2
near = 0.1
far = 1000

[questionnaire]
scale_points = 7
items = ["I noticed differences", "Viewing was comfortable"]
)";

// kValidProtocol with `from` (which must occur exactly once) replaced by `to`.
std::string mutated(std::string_view from, std::string_view to) {
    std::string text(kValidProtocol);
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "mutation target not found: " << from;
    EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "mutation target not unique: " << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

std::filesystem::path source_dir() {
    const char* dir = std::getenv("MONOPLANE_SOURCE_DIR");  // set by ctest
    return dir == nullptr ? std::filesystem::path{} : std::filesystem::path(dir);
}

TEST(StudyProtocol, ValidTextParsesWithEveryValue) {
    const Result<Protocol> p = parse_protocol(kValidProtocol, "test.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->name, "test");
    EXPECT_EQ(p->scenes, (std::vector<std::string>{"beams", "landscape", "spheres"}));
    EXPECT_EQ(p->mono_planes, (std::vector<double>{1.6, 3, 8, 31, 39.5}));
    EXPECT_EQ(p->alternatives[0], RenderMode::Stereo);
    EXPECT_EQ(p->alternatives[1], RenderMode::Hybrid);
    EXPECT_EQ(p->order, TrialOrder::Randomized);
    EXPECT_EQ(p->first_scene, FirstSceneBalance::LatinSquare);
    EXPECT_TRUE(p->require_both_viewed);
    EXPECT_EQ(p->practice_trials, 2);
    EXPECT_EQ(p->near, 0.1);
    EXPECT_EQ(p->far, 1000.0);
    EXPECT_EQ(p->questionnaire.scale_points, 7);
    EXPECT_EQ(p->questionnaire.items,
              (std::vector<std::string>{"I noticed differences", "Viewing was comfortable"}));
    EXPECT_EQ(p->trials_per_session(), 15u);
    EXPECT_EQ(p->source, "test.toml");
    EXPECT_EQ(p->text, kValidProtocol);
}

// Every single-pass stereo mode may be an alternative, as stereo is.
TEST(StudyProtocol, SinglePassStereoModesAreAlternatives) {
    const std::pair<std::string, RenderMode> modes[] = {
        {"stereo-multiview", RenderMode::StereoMultiview},
        {"stereo-gs", RenderMode::StereoGs},
        {"stereo-instanced", RenderMode::StereoInstanced}};
    for (const auto& [name, mode] : modes) {
        const Result<Protocol> p = parse_protocol(
            "name = \"single pass\"\n"
            "scenes = [\"beams\"]\n"
            "mono_planes = [8]\n"
            "alternatives = [\"" +
                name + "\", \"hybrid\"]\n",
            "single-pass.toml");
        ASSERT_TRUE(p.ok()) << name << ": " << p.error().message;
        EXPECT_EQ(p->alternatives[0], mode) << name;
        EXPECT_EQ(p->alternatives[1], RenderMode::Hybrid);
    }
}

TEST(StudyProtocol, OptionalKeysTakeTheirDefaults) {
    const Result<Protocol> p = parse_protocol(R"(name = "minimal"
scenes = ["spheres"]
mono_planes = [8]
alternatives = ["stereo-multiview", "hybrid-farfield"]
)",
                                              "minimal.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    const Protocol defaults;
    EXPECT_EQ(p->alternatives[0], RenderMode::StereoMultiview);
    EXPECT_EQ(p->alternatives[1], RenderMode::HybridFarfield);
    EXPECT_EQ(p->order, defaults.order);
    EXPECT_EQ(p->first_scene, defaults.first_scene);
    EXPECT_EQ(p->require_both_viewed, defaults.require_both_viewed);
    EXPECT_EQ(p->practice_trials, defaults.practice_trials);
    EXPECT_EQ(p->near, 0.1);
    EXPECT_EQ(p->far, 1000.0);
    EXPECT_TRUE(p->questionnaire.items.empty());
    EXPECT_EQ(p->questionnaire.scale_points, 7);
    EXPECT_EQ(p->trials_per_session(), 1u);
    // No study-day keys: one session of one repetition, no screens, no variables.
    EXPECT_EQ(p->day.sessions, 1);
    EXPECT_EQ(p->day.repetitions, 1);
    EXPECT_EQ(p->day.blocking, Blocking::Scene);
    EXPECT_EQ(p->day.text_height_deg, 1.0);
    EXPECT_FALSE(p->day.has_screens());
    EXPECT_TRUE(p->day.variables.empty());
}

TEST(StudyProtocol, OtherChoicesAreRead) {
    std::string text = mutated("order = \"randomized\"", "order = \"fixed\"");
    text.replace(text.find("\"latin-square\""), 14, "\"random\"");
    text.replace(text.find("require_both_viewed = true"), 26, "require_both_viewed = false");
    text.replace(text.find("practice_trials = 2"), 19, "practice_trials = 0");
    const Result<Protocol> p = parse_protocol(text, "test.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->order, TrialOrder::Fixed);
    EXPECT_EQ(p->first_scene, FirstSceneBalance::Random);
    EXPECT_FALSE(p->require_both_viewed);
    EXPECT_EQ(p->practice_trials, 0);
}

// papers/000 Sect. 6.1: 3 scenes x 10 distances, stereo (reference) vs hybrid, randomized.
TEST(StudyProtocol, Fink2019FileHasThePapersDesign) {
    if (source_dir().empty()) GTEST_SKIP() << "MONOPLANE_SOURCE_DIR not set (run through ctest)";
    const Result<Protocol> p = load_protocol(source_dir() / "protocols" / "fink2019.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->name, "fink2019");
    EXPECT_EQ(p->scenes, (std::vector<std::string>{"beams", "landscape", "spheres"}));
    EXPECT_EQ(p->mono_planes, (std::vector<double>{1.6, 3, 5, 8, 12, 16, 20, 25, 31, 39.5}));
    for (double named : {1.6, 3.0, 8.0, 31.0, 39.5}) {
        EXPECT_NE(std::ranges::find(p->mono_planes, named), p->mono_planes.end()) << named;
    }
    EXPECT_EQ(p->trials_per_session(), 30u);
    EXPECT_EQ(p->alternatives[0], RenderMode::Stereo);
    EXPECT_EQ(p->alternatives[1], RenderMode::Hybrid);
    EXPECT_EQ(p->order, TrialOrder::Randomized);
    EXPECT_EQ(p->first_scene, FirstSceneBalance::LatinSquare);
    EXPECT_TRUE(p->require_both_viewed);
    EXPECT_EQ(p->practice_trials, 2);
    EXPECT_EQ(p->near, 0.1);
    EXPECT_EQ(p->far, 1000.0);
    EXPECT_EQ(p->questionnaire.scale_points, 7);
    EXPECT_EQ(p->questionnaire.items.size(), 6u);
    EXPECT_NE(p->source.find("fink2019.toml"), std::string::npos);
    EXPECT_FALSE(p->text.empty());
    // papers/000 Sect. 4.5: the study was rendered with TAA.
    EXPECT_EQ(p->render.anti_aliasing, "taa");
    EXPECT_EQ(p->render.ssao, "off");
    // Sect. 6.1's introduction, a rest between the scene blocks, and no variable that a session
    // without --var would lack.
    EXPECT_EQ(p->day.instructions.size(), 3u);
    EXPECT_TRUE(p->day.ready && p->day.end);
    ASSERT_TRUE(p->day.breaks);
    EXPECT_EQ(p->day.breaks, (BreakSettings{0, true, 30.0, p->day.breaks->text}));
    EXPECT_EQ(p->day.sessions, 1);
    EXPECT_TRUE(std::ranges::none_of(p->day.variables, &ParticipantVariable::required));
}

TEST(StudyProtocol, RenderTableIsReadAndDefaultsToNoAntiAliasing) {
    const Result<Protocol> defaults = parse_protocol(kValidProtocol, "test.toml");
    ASSERT_TRUE(defaults.ok()) << defaults.error().message;
    EXPECT_EQ(defaults->render, (RenderSettings{"none", "off", "low"}));
    EXPECT_EQ(defaults->missed_frame_threshold, 0.05);
    const Result<Protocol> strict = parse_protocol(
        mutated("far = 1000\n", "far = 1000\nmissed_frame_threshold = 0.01\n"), "test.toml");
    ASSERT_TRUE(strict.ok()) << strict.error().message;
    EXPECT_EQ(strict->missed_frame_threshold, 0.01);
    const Result<Protocol> p = parse_protocol(
        std::string(kValidProtocol) +
            "\n[render]\nanti_aliasing = \"taa\"\nssao = \"stereo\"\ndetail = \"medium\"\n",
        "test.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->render, (RenderSettings{"taa", "stereo", "medium"}));
    // MSAA is fine when both alternatives are stereo forms.
    const std::string stereo_forms = mutated("alternatives = [\"stereo\", \"hybrid\"]",
                                             "alternatives = [\"stereo\", \"stereo-multiview\"]") +
                                     "\n[render]\nanti_aliasing = \"msaa4\"\n";
    const Result<Protocol> msaa = parse_protocol(stereo_forms, "test.toml");
    ASSERT_TRUE(msaa.ok()) << msaa.error().message;
    EXPECT_EQ(msaa->render.anti_aliasing, "msaa4");
}

TEST(StudyProtocol, AutoTableConfiguresHybridAuto) {
    const std::string text =
        mutated("alternatives = [\"stereo\", \"hybrid\"]",
                "alternatives = [\"stereo\", \"hybrid-auto\"]") +
        "\n[auto]\nerror_budget_arcmin = 4.5\nmeasure = \"disparity\"\nstep_arcmin = 0.5\n"
        "time_budget_ms = 11.1\n";
    const Result<Protocol> p = parse_protocol(text, "test.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->alternatives[1], RenderMode::HybridAuto);
    EXPECT_EQ(p->auto_plane, (AutoPlaneSettings{4.5, "disparity", 0.5, 11.1}));
    // Without the table: the defaults (6 arcmin, each eye's error, 0.25 arcmin steps, no time).
    const Result<Protocol> defaults =
        parse_protocol(mutated("alternatives = [\"stereo\", \"hybrid\"]",
                               "alternatives = [\"stereo\", \"hybrid-auto\"]"),
                       "test.toml");
    ASSERT_TRUE(defaults.ok()) << defaults.error().message;
    EXPECT_EQ(defaults->auto_plane, AutoPlaneSettings{});
}

TEST(StudyProtocol, DemoFileIsShort) {
    if (source_dir().empty()) GTEST_SKIP() << "MONOPLANE_SOURCE_DIR not set (run through ctest)";
    const Result<Protocol> p = load_protocol(source_dir() / "protocols" / "demo.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->name, "demo");
    EXPECT_EQ(p->scenes, (std::vector<std::string>{"beams", "landscape", "spheres"}));
    EXPECT_EQ(p->mono_planes, (std::vector<double>{3, 8}));
    EXPECT_EQ(p->trials_per_session(), 6u);
    EXPECT_EQ(p->alternatives[0], RenderMode::Stereo);
    EXPECT_EQ(p->alternatives[1], RenderMode::Hybrid);
    EXPECT_EQ(p->practice_trials, 1);
    EXPECT_EQ(p->questionnaire.items.size(), 2u);
    EXPECT_EQ(p->day.instructions.size(), 1u);  // the main job's demo shows one page
    EXPECT_FALSE(p->day.breaks);
    EXPECT_TRUE(p->day.variables.empty());
}

TEST(StudyProtocol, LoadKeepsPathAndText) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "monoplane_study_protocol_test.toml";
    std::ofstream(path, std::ios::binary) << kValidProtocol;
    const Result<Protocol> p = load_protocol(path);
    std::filesystem::remove(path);
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->source, path.string());
    EXPECT_EQ(p->text, kValidProtocol);
    EXPECT_EQ(p->text_hash, parse_protocol(kValidProtocol, "other name").value().text_hash);
}

TEST(StudyProtocol, ErrorsFromAFileNameThePath) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "monoplane_study_protocol_bad_test.toml";
    std::ofstream(path, std::ios::binary) << mutated("practice_trials = 2", "practice_trials = 99");
    const Result<Protocol> p = load_protocol(path);
    std::filesystem::remove(path);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().message.rfind(path.string() + ":8:", 0), 0u) << p.error().message;
}

TEST(StudyProtocol, MissingFileAndDirectoryAreRefused) {
    const std::filesystem::path missing =
        std::filesystem::temp_directory_path() / "monoplane_no_such_protocol.toml";
    const Result<Protocol> p = load_protocol(missing);
    ASSERT_FALSE(p.ok());
    EXPECT_NE(p.error().message.find(missing.string()), std::string::npos) << p.error().message;
    const Result<Protocol> dir = load_protocol(std::filesystem::temp_directory_path());
    ASSERT_FALSE(dir.ok());
    EXPECT_NE(dir.error().message.find("directory"), std::string::npos) << dir.error().message;
}

TEST(StudyProtocol, HashIsFnv1a64OfTheTextAndStable) {
    const Result<Protocol> a = parse_protocol(kValidProtocol, "a.toml");
    const Result<Protocol> b = parse_protocol(kValidProtocol, "b.toml");
    const Result<Protocol> changed =
        parse_protocol(std::string(kValidProtocol) + "# a comment\n", "a.toml");
    ASSERT_TRUE(a.ok() && b.ok() && changed.ok());
    EXPECT_EQ(a->text_hash, b->text_hash);           // the source name is no part of the protocol
    EXPECT_NE(a->text_hash, changed->text_hash);     // any edit is a new version, comments too
    std::uint64_t expected = 0xcbf29ce484222325ull;  // FNV-1a 64 offset basis and prime
    for (const char c : kValidProtocol) {
        expected = (expected ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
    }
    EXPECT_EQ(a->text_hash, expected);
}

TEST(StudyProtocol, AllProblemsAreReportedInDocumentOrder) {
    std::string text = mutated("practice_trials = 2", "practice_trials = -1");
    text.replace(text.find("\"hybrid\"]"), 9, "\"hybird\"]");
    text.replace(text.find("scale_points = 7"), 16, "scale_points = 20");
    text.replace(text.find("name = \"test\"\n"), 14, "");  // lines shift up by one
    const Result<Protocol> p = parse_protocol(text, "test.toml");
    ASSERT_FALSE(p.ok());
    const std::string& message = p.error().message;
    EXPECT_EQ(message.find("test.toml: key 'name'"), 0u) << message;
    const std::size_t alternatives = message.find("\ntest.toml:3:");
    const std::size_t practice = message.find("\ntest.toml:7:");
    const std::size_t scale = message.find("\ntest.toml:12:");
    EXPECT_NE(alternatives, std::string::npos) << message;
    EXPECT_NE(practice, std::string::npos) << message;
    EXPECT_NE(scale, std::string::npos) << message;
    EXPECT_LT(alternatives, practice);
    EXPECT_LT(practice, scale);
    EXPECT_EQ(std::ranges::count(message, '\n'), 3) << message;
}

struct MalformedCase {
    std::string_view what;
    std::string_view from;
    std::string_view to;
    // Each must occur in the message: the line ("test.toml:5:") and the key matter most.
    std::vector<std::string_view> expected;
};

class MalformedProtocol : public testing::TestWithParam<MalformedCase> {};

TEST_P(MalformedProtocol, IsRefusedNamingSourceLineAndKey) {
    const MalformedCase& c = GetParam();
    const Result<Protocol> p = parse_protocol(mutated(c.from, c.to), "test.toml");
    ASSERT_FALSE(p.ok()) << c.what;
    const std::string& message = p.error().message;
    EXPECT_EQ(message.rfind("test.toml", 0), 0u) << message;
    for (std::string_view expected : c.expected) {
        EXPECT_NE(message.find(expected), std::string::npos)
            << c.what << ": expected \"" << expected << "\" in:\n"
            << message;
    }
}

const MalformedCase kMalformedCases[] = {
    // Required keys. A key missing from the root has no line to point at.
    {"missing name", "name = \"test\"\n", "", {"test.toml: key 'name': required key is missing"}},
    {"missing scenes",
     "scenes = [\"beams\", \"landscape\", \"spheres\"]\n",
     "",
     {"test.toml: key 'scenes'", "missing", "beams, landscape, spheres"}},
    {"missing mono_planes",
     "mono_planes = [1.6, 3, 8, 31, 39.5]\n",
     "",
     {"test.toml: key 'mono_planes'", "missing"}},
    {"missing alternatives",
     "alternatives = [\"stereo\", \"hybrid\"]\n",
     "",
     {"test.toml: key 'alternatives'", "missing"}},
    {"missing questionnaire items",
     "items = [\"I noticed differences\", \"Viewing was comfortable\"]\n",
     "",
     {"test.toml:12:", "'questionnaire.items'", "missing"}},
    // Unknown keys, misspelt and foreign, at the top level and in [questionnaire].
    {"misspelt key",
     "practice_trials = 2",
     "practise_trials = 2",
     {"test.toml:8:", "'practise_trials'", "did you mean 'practice_trials'"}},
    {"foreign key",
     "far = 1000\n",
     "far = 1000\nparticipants = 20\n",
     {"test.toml:11:", "'participants'", "known keys: name, scenes"}},
    {"misspelt questionnaire key",
     "scale_points = 7",
     "scale_point = 7",
     {"test.toml:13:", "'questionnaire.scale_point'", "did you mean 'questionnaire.scale_points'"}},
    {"unknown table",
     "[questionnaire]",
     "[questionaire]",
     {"test.toml:12:", "'questionaire'", "did you mean 'questionnaire'"}},
    // Wrong types.
    {"numeric name",
     "name = \"test\"",
     "name = 7",
     {"test.toml:1:", "'name'", "string", "integer"}},
    {"empty name", "name = \"test\"", "name = \" \"", {"test.toml:1:", "'name'", "empty"}},
    {"scenes as a string",
     "scenes = [\"beams\", \"landscape\", \"spheres\"]",
     "scenes = \"beams\"",
     {"test.toml:2:", "'scenes'", "array", "but is a string"}},
    {"scene as a number",
     "\"landscape\", \"spheres\"]",
     "\"landscape\", 3]",
     {"test.toml:2:", "'scenes'", "element 3", "string"}},
    {"mono_planes as a number",
     "mono_planes = [1.6, 3, 8, 31, 39.5]",
     "mono_planes = 8",
     {"test.toml:3:", "'mono_planes'", "array"}},
    {"mono plane as a string",
     "[1.6, 3, 8, 31, 39.5]",
     "[1.6, 3, \"8\", 31, 39.5]",
     {"test.toml:3:", "'mono_planes'", "element 3", "number", "string"}},
    {"alternatives as a string",
     "alternatives = [\"stereo\", \"hybrid\"]",
     "alternatives = \"stereo\"",
     {"test.toml:4:", "'alternatives'", "array"}},
    {"order as a number",
     "order = \"randomized\"",
     "order = 1",
     {"test.toml:5:", "'order'", "randomized, fixed"}},
    {"require_both_viewed as a string",
     "require_both_viewed = true",
     "require_both_viewed = \"yes\"",
     {"test.toml:7:", "'require_both_viewed'", "boolean"}},
    {"fractional practice_trials",
     "practice_trials = 2",
     "practice_trials = 2.5",
     {"test.toml:8:", "'practice_trials'", "integer"}},
    {"practice_trials as a string",
     "practice_trials = 2",
     "practice_trials = \"2\"",
     {"test.toml:8:", "'practice_trials'", "integer"}},
    {"near as a string", "near = 0.1", "near = \"0.1\"", {"test.toml:9:", "'near'", "number"}},
    {"far as a boolean", "far = 1000", "far = true", {"test.toml:10:", "'far'", "number"}},
    {"questionnaire as a value",
     "[questionnaire]\nscale_points = 7\n"
     "items = [\"I noticed differences\", \"Viewing was comfortable\"]\n",
     "questionnaire = 3\n",
     {"test.toml:12:", "'questionnaire'", "table"}},
    {"float scale_points",
     "scale_points = 7",
     "scale_points = 7.0",
     {"test.toml:13:", "'questionnaire.scale_points'", "integer"}},
    {"items as a string",
     "items = [\"I noticed differences\", \"Viewing was comfortable\"]",
     "items = \"I noticed differences\"",
     {"test.toml:14:", "'questionnaire.items'", "array"}},
    {"item as a number",
     "\"Viewing was comfortable\"]",
     "42]",
     {"test.toml:14:", "'questionnaire.items'", "element 2", "string"}},
    // Unknown values.
    {"unknown scene",
     "\"landscape\"",
     "\"forest\"",
     {"test.toml:2:", "'scenes'", "'forest'", "beams, landscape, spheres"}},
    {"misspelt scene",
     "\"spheres\"]",
     "\"sphere\"]",
     {"test.toml:2:", "'scenes'", "did you mean 'spheres'"}},
    {"scene in an unsupported file format",
     "\"landscape\"",
     "\"room.obj\"",
     {"test.toml:2:20:", "'scenes'", "'room.obj'", "a glTF file ending in .gltf or .glb"}},
    {"scene file with a comma",
     "\"landscape\"",
     "\"a,b.glb\"",
     {"test.toml:2:20:", "'scenes'", "scene file 'a,b.glb' has a comma"}},
    {"scene file twice",
     "\"landscape\", \"spheres\"",
     "\"room.GLB\", \"room.GLB\"",
     {"test.toml:2:32:", "'scenes'", "duplicate scene 'room.GLB'"}},
    {"unknown mode",
     "\"hybrid\"]",
     "\"hybird\"]",
     {"test.toml:4:", "'alternatives'", "'hybird'",
      "stereo, stereo-multiview, stereo-gs, stereo-instanced, hybrid, hybrid-farfield"}},
    {"identical alternatives",
     "[\"stereo\", \"hybrid\"]",
     "[\"hybrid\", \"hybrid\"]",
     {"test.toml:4:", "'alternatives'", "both alternatives are 'hybrid'", "different"}},
    {"three alternatives",
     "[\"stereo\", \"hybrid\"]",
     "[\"stereo\", \"hybrid\", \"hybrid-farfield\"]",
     {"test.toml:4:", "'alternatives'", "exactly two", "lists 3"}},
    {"one alternative",
     "[\"stereo\", \"hybrid\"]",
     "[\"stereo\"]",
     {"test.toml:4:", "'alternatives'", "exactly two", "lists 1"}},
    {"unknown order",
     "order = \"randomized\"",
     "order = \"random\"",
     {"test.toml:5:", "'order'", "'random'", "allowed: randomized, fixed",
      "did you mean 'randomized'"}},
    {"shortened first_scene",
     "first_scene = \"latin-square\"",
     "first_scene = \"latin\"",
     {"test.toml:6:", "'first_scene'", "did you mean 'latin-square'"}},
    {"unknown first_scene",
     "first_scene = \"latin-square\"",
     "first_scene = \"latin-squares\"",
     {"test.toml:6:", "'first_scene'", "latin-square, random, fixed",
      "did you mean 'latin-square'"}},
    // Distances.
    {"nan mono plane",
     "[1.6, 3, 8, 31, 39.5]",
     "[1.6, 3, nan, 31, 39.5]",
     {"test.toml:3:", "'mono_planes'", "nan", "finite"}},
    {"infinite mono plane",
     "[1.6, 3, 8, 31, 39.5]",
     "[1.6, 3, 8, 31, inf]",
     {"test.toml:3:", "'mono_planes'", "inf", "finite"}},
    {"negative mono plane",
     "[1.6, 3, 8, 31, 39.5]",
     "[1.6, -3, 8, 31, 39.5]",
     {"test.toml:3:", "'mono_planes'", "-3", "positive"}},
    {"zero mono plane",
     "[1.6, 3, 8, 31, 39.5]",
     "[0, 3, 8, 31, 39.5]",
     {"test.toml:3:", "'mono_planes'", "element 1 = 0", "positive"}},
    {"mono plane at near",
     "[1.6, 3, 8, 31, 39.5]",
     "[0.1, 3, 8, 31, 39.5]",
     {"test.toml:3:", "'mono_planes'", "0.1 m is not strictly inside (near, far) = (0.1, 1000)"}},
    {"mono plane at far",
     "[1.6, 3, 8, 31, 39.5]",
     "[1.6, 3, 8, 31, 1000]",
     {"test.toml:3:", "'mono_planes'", "1000 m is not strictly inside"}},
    {"mono plane beyond a shorter far",
     "far = 1000",
     "far = 20",
     {"test.toml:3:", "'mono_planes'", "31 m is not strictly inside (near, far) = (0.1, 20)"}},
    {"mono plane before a longer near",
     "near = 0.1",
     "near = 2",
     {"test.toml:3:", "'mono_planes'", "element 1 = 1.6"}},
    {"duplicate mono plane",
     "[1.6, 3, 8, 31, 39.5]",
     "[1.6, 3, 8, 3.0, 39.5]",
     {"test.toml:3:", "'mono_planes'", "duplicate distance 3 m"}},
    {"duplicate scene",
     "[\"beams\", \"landscape\", \"spheres\"]",
     "[\"beams\", \"spheres\", \"beams\"]",
     {"test.toml:2:", "'scenes'", "duplicate scene 'beams'"}},
    {"near not positive", "near = 0.1", "near = 0", {"test.toml:9:", "'near'", "> 0"}},
    {"far infinite", "far = 1000", "far = inf", {"test.toml:10:", "'far'", "finite"}},
    {"near beyond far",
     "near = 0.1",
     "near = 2000",
     {"test.toml:10:", "'far'", "near < far", "near = 2000 m, far = 1000 m"}},
    // Empty lists.
    {"no scenes",
     "scenes = [\"beams\", \"landscape\", \"spheres\"]",
     "scenes = []",
     {"test.toml:2:", "'scenes'", "must not be empty"}},
    {"no mono planes",
     "mono_planes = [1.6, 3, 8, 31, 39.5]",
     "mono_planes = []",
     {"test.toml:3:", "'mono_planes'", "must not be empty"}},
    {"no alternatives",
     "alternatives = [\"stereo\", \"hybrid\"]",
     "alternatives = []",
     {"test.toml:4:", "'alternatives'", "must not be empty"}},
    {"no questionnaire items",
     "items = [\"I noticed differences\", \"Viewing was comfortable\"]",
     "items = []",
     {"test.toml:14:", "'questionnaire.items'", "must not be empty"}},
    // Ranges.
    {"negative practice",
     "practice_trials = 2",
     "practice_trials = -1",
     {"test.toml:8:", "'practice_trials'", "-1", "0..50"}},
    {"too much practice",
     "practice_trials = 2",
     "practice_trials = 51",
     {"test.toml:8:", "'practice_trials'", "51", "0..50"}},
    {"one-point scale",
     "scale_points = 7",
     "scale_points = 1",
     {"test.toml:13:", "'questionnaire.scale_points'", "2..11"}},
    {"twelve-point scale",
     "scale_points = 7",
     "scale_points = 12",
     {"test.toml:13:", "'questionnaire.scale_points'", "12", "2..11"}},
    {"empty item",
     "\"Viewing was comfortable\"]",
     "\"\"]",
     {"test.toml:14:", "'questionnaire.items'", "item 2 is empty"}},
    {"blank item",
     "[\"I noticed differences\",",
     "[\"  \",",
     {"test.toml:14:", "'questionnaire.items'", "item 1 is empty"}},
    {"empty item after a number",
     "[\"I noticed differences\", \"Viewing was comfortable\"]",
     "[7, \"\"]",
     {"test.toml:14:", "'questionnaire.items'", "element 1 must be a string", "item 2 is empty"}},
    // Malformed TOML: the parser's message with its place.
    {"unterminated string",
     "name = \"test\"",
     "name = \"test",
     {"test.toml:1:", "TOML syntax error"}},
    {"unclosed array",
     "[1.6, 3, 8, 31, 39.5]",
     "[1.6, 3, 8, 31, 39.5",
     {"test.toml:", "TOML syntax error"}},
    {"key given twice",
     "far = 1000",
     "far = 1000\nfar = 500",
     {"test.toml:11:", "TOML syntax error"}},
    // The [render] table (appended after [questionnaire]: line 16 on).
    {"unknown anti-aliasing",
     "Viewing was comfortable\"]\n",
     "Viewing was comfortable\"]\n\n[render]\nanti_aliasing = \"fxaa\"\n",
     {"test.toml:17:", "'render.anti_aliasing'", "unknown value 'fxaa'", "none, taa, msaa2"}},
    {"MSAA with a hybrid alternative",
     "Viewing was comfortable\"]\n",
     "Viewing was comfortable\"]\n\n[render]\nanti_aliasing = \"msaa4\"\n",
     {"test.toml:17:", "'render.anti_aliasing'", "'msaa4'", "stereo forms", "use 'taa'"}},
    {"misspelt SSAO",
     "Viewing was comfortable\"]\n",
     "Viewing was comfortable\"]\n\n[render]\nssao = \"per_eye\"\n",
     {"test.toml:17:", "'render.ssao'", "did you mean 'per-eye'"}},
    {"detail as a number",
     "Viewing was comfortable\"]\n",
     "Viewing was comfortable\"]\n\n[render]\ndetail = 2\n",
     {"test.toml:17:", "'render.detail'", "string", "integer"}},
    {"unknown render key",
     "Viewing was comfortable\"]\n",
     "Viewing was comfortable\"]\n\n[render]\nvsync = true\n",
     {"test.toml:17:", "'render.vsync'", "known keys in [render]: anti_aliasing, ssao, detail"}},
    {"missed-frame share above 1",
     "far = 1000\n",
     "far = 1000\nmissed_frame_threshold = 5\n",
     {"test.toml:11:", "'missed_frame_threshold'", "in [0, 1]"}},
    {"missed-frame share as text",
     "far = 1000\n",
     "far = 1000\nmissed_frame_threshold = \"5%\"\n",
     {"test.toml:11:", "'missed_frame_threshold'", "a number", "string"}},
    {"render as a value",
     "far = 1000\n",
     "far = 1000\nrender = \"taa\"\n",
     {"test.toml:11:", "'render'", "table"}},
    // The [auto] table (appended after [questionnaire]: line 16 on).
    {"auto without a hybrid-auto alternative",
     "Viewing was comfortable\"]\n",
     "Viewing was comfortable\"]\n\n[auto]\nerror_budget_arcmin = 5\n",
     {"test.toml:16:", "'auto'", "neither alternative is hybrid-auto"}},
    {"a budget that is not positive",
     "Viewing was comfortable\"]\n",
     "Viewing was comfortable\"]\n\n[auto]\nerror_budget_arcmin = -2\n",
     {"test.toml:17:", "'auto.error_budget_arcmin'", "positive number of arcminutes"}},
    {"an unknown measure",
     "Viewing was comfortable\"]\n",
     "Viewing was comfortable\"]\n\n[auto]\nmeasure = \"pixels\"\n",
     {"test.toml:17:", "'auto.measure'", "not eye or disparity"}},
    {"an unknown auto key",
     "Viewing was comfortable\"]\n",
     "Viewing was comfortable\"]\n\n[auto]\nbudget = 5\n",
     {"test.toml:17:", "'auto.budget'", "error_budget_arcmin"}},
    // A study day (study_day_protocol_test.cpp has every case; these show the root's key list
    // knows the new keys and the tables sit where the others do).
    {"no repetitions",
     "far = 1000\n",
     "far = 1000\nrepetitions = 0\n",
     {"test.toml:11:", "'repetitions'", "outside the allowed range 1..50"}},
    {"misspelt sessions",
     "far = 1000\n",
     "far = 1000\nsesions = 2\n",
     {"test.toml:11:1: key 'sesions': unknown key (did you mean 'sessions'?)"}},
    {"misspelt breaks table",
     "Viewing was comfortable\"]\n",
     "Viewing was comfortable\"]\n\n[brakes]\nevery_trials = 5\n",
     {"test.toml:16:2: key 'brakes': unknown key (did you mean 'breaks'?)"}},
    {"a break of an hour",
     "Viewing was comfortable\"]\n",
     "Viewing was comfortable\"]\n\n[breaks]\nevery_trials = 5\nmin_s = 3600\n",
     {"test.toml:18:", "'breaks.min_s'", "a break longer than 30 minutes is not a break"}},
    {"a required variable without a type",
     "Viewing was comfortable\"]\n",
     "Viewing was comfortable\"]\n\n[[variables]]\nname = \"age\"\nrequired = true\n",
     {"test.toml:16:1: key 'variables.type': required key is missing"}},
};

// Scenes that name glTF files (docs/scenes.md, "glTF scenes in a study"): a protocol file and its
// scene files in a folder of their own.
class ProtocolSceneFiles : public testing::Test {
  protected:
    void SetUp() override {
        std::string pattern =
            (std::filesystem::path(testing::TempDir()) / "protocol_scenes_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        root_ = pattern;
        std::filesystem::create_directories(root_ / "protocols" / "models");
        std::filesystem::create_directories(root_ / "shared");
        touch(root_ / "protocols" / "models" / "room.glb");
        touch(root_ / "shared" / "hall.gltf");
    }
    void TearDown() override { std::filesystem::remove_all(root_); }

    static void touch(const std::filesystem::path& path) { std::ofstream(path) << "x"; }

    // The protocol file protocols/p.toml with `scenes` as its second line.
    std::filesystem::path write_protocol(const std::string& scenes) const {
        std::filesystem::path path = root_ / "protocols" / "p.toml";
        std::ofstream(path) << "name = \"files\"\nscenes = " << scenes
                            << "\nmono_planes = [3, 8]\nalternatives = [\"stereo\", \"hybrid\"]\n";
        return path;
    }

    std::filesystem::path root_;
};

TEST_F(ProtocolSceneFiles, FileEntriesKeepTheirLabelAndResolveAgainstTheProtocolsFolder) {
    const std::string absolute = (root_ / "shared" / "hall.gltf").string();
    const Result<Protocol> p =
        load_protocol(write_protocol("[\"beams\", \"models/room.glb\", \"" + absolute + "\"]"));
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->scenes, (std::vector<std::string>{"beams", "models/room.glb", absolute}));
    ASSERT_EQ(p->scene_files.size(), 2u);  // built-in scenes are no files
    EXPECT_EQ(p->scene_files.at("models/room.glb"), root_ / "protocols" / "models" / "room.glb");
    EXPECT_EQ(p->scene_files.at(absolute), root_ / "shared" / "hall.gltf");
    EXPECT_TRUE(p->scene_files.at("models/room.glb").is_absolute());
    // "../shared/hall.gltf" is the same file by another name: listed once only.
    const Result<Protocol> twice =
        load_protocol(write_protocol("[\"../shared/hall.gltf\", \"" + absolute + "\"]"));
    ASSERT_FALSE(twice.ok());
    EXPECT_NE(twice.error().message.find(":2:34: key 'scenes': scene file '" + absolute +
                                         "' is the same file as '../shared/hall.gltf'"),
              std::string::npos)
        << twice.error().message;
}

TEST_F(ProtocolSceneFiles, AMissingFileIsALocatedProblem) {
    const std::filesystem::path path =
        write_protocol("[\"models/room.glb\", \"models/gone.gltf\", \"models\"]");
    const Result<Protocol> p = load_protocol(path);
    ASSERT_FALSE(p.ok());
    const std::string& message = p.error().message;
    // Column 30: the second element, where the user must look.
    const std::string expected = path.string() + ":2:30: key 'scenes': scene file " +
                                 "'models/gone.gltf' not found (looked for " +
                                 (root_ / "protocols" / "models" / "gone.gltf").string() + ";";
    EXPECT_NE(message.find(expected), std::string::npos) << message;
    // "models" (a folder) is neither a built-in scene nor a file name: reported too.
    EXPECT_NE(message.find(":2:50: key 'scenes': unknown scene 'models'"), std::string::npos)
        << message;
}

TEST_F(ProtocolSceneFiles, AFolderNamedLikeAFileIsRefused) {
    std::filesystem::create_directories(root_ / "protocols" / "odd.glb");
    const Result<Protocol> p = load_protocol(write_protocol("[\"odd.glb\"]"));
    ASSERT_FALSE(p.ok());
    EXPECT_NE(p.error().message.find(":2:11: key 'scenes': scene file 'odd.glb' is not a regular "
                                     "file ("),
              std::string::npos)
        << p.error().message;
}

// Text alone (a session's stored protocol, read by resume and analyze on any machine) has no
// folder: file entries are checked for their form only and resolve nowhere.
TEST_F(ProtocolSceneFiles, TextWithoutAFolderChecksTheFormOnly) {
    const Result<Protocol> p =
        parse_protocol(mutated("\"landscape\"", "\"nowhere/x.glb\""), "session 1");
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->scenes, (std::vector<std::string>{"beams", "nowhere/x.glb", "spheres"}));
    EXPECT_TRUE(p->scene_files.empty());
    // With a folder, the same text is checked against it.
    const Result<Protocol> checked = parse_protocol(mutated("\"landscape\"", "\"models/room.glb\""),
                                                    "in folder", root_ / "protocols");
    ASSERT_TRUE(checked.ok()) << checked.error().message;
    EXPECT_EQ(checked->scene_files.at("models/room.glb"),
              root_ / "protocols" / "models" / "room.glb");
}

INSTANTIATE_TEST_SUITE_P(AllClasses, MalformedProtocol, testing::ValuesIn(kMalformedCases),
                         [](const testing::TestParamInfo<MalformedCase>& info) {
                             std::string name;
                             for (char c : info.param.what) {
                                 name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                             }
                             return name;
                         });

}  // namespace
}  // namespace monoplane::study
