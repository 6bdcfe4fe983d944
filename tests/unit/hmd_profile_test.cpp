// HMD profiles: the built-ins carry the paper's values, and every class of
// malformed profile is refused with a message that names the source and the offending key.
#include <gtest/gtest.h>

#include <array>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "hmd/profile.h"

namespace monoplane::hmd {
namespace {

// A valid profile that every malformed case below mutates in one place.
constexpr std::string_view kValidProfile = R"(name = "test headset"
ipd = 0.064
width = 1344
height = 1512

[left]
tan_left = -1.391937
tan_right = 1.247409
tan_up = 1.464287
tan_down = -1.468819

[right]
tan_left = -1.246557
tan_right = 1.398447
tan_up = 1.472458
tan_down = -1.465505
)";

// kValidProfile with `from` (which must occur exactly once) replaced by `to`.
std::string mutated(std::string_view from, std::string_view to) {
    std::string text(kValidProfile);
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "mutation target not found: " << from;
    EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "mutation target not unique: " << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

void expect_tangents(const rig::Tangents& actual, double left, double right, double down,
                     double up) {
    EXPECT_EQ(actual.left, left);
    EXPECT_EQ(actual.right, right);
    EXPECT_EQ(actual.down, down);
    EXPECT_EQ(actual.up, up);
}

TEST(HmdProfile, ValidTextParses) {
    const Result<HmdProfile> profile = parse_hmd_profile(kValidProfile, "test.toml");
    ASSERT_TRUE(profile.ok()) << profile.error().message;
    EXPECT_EQ(profile->name, "test headset");
    EXPECT_EQ(profile->source, "test.toml");
}

TEST(HmdProfile, BuiltinNamesInOrder) {
    EXPECT_EQ(builtin_hmd_names(), (std::vector<std::string>{"vive", "vive-pro", "symmetric-90",
                                                             "symmetric-110", "canted-15"}));
}

TEST(HmdProfile, EveryBuiltinLoads) {
    for (const std::string& name : builtin_hmd_names()) {
        const Result<HmdProfile> profile = load_hmd_profile(name);
        ASSERT_TRUE(profile.ok()) << name << ": " << profile.error().message;
        EXPECT_EQ(profile->source, "built-in " + name);
        EXPECT_FALSE(profile->name.empty());
        EXPECT_EQ(profile->ipd, 0.064) << name;
    }
}

// The calibration quoted in papers/000 Sect. 4.2 (OpenVR signs: t = -tan_up, b = -tan_down).
TEST(HmdProfile, ViveHasThePapersCalibration) {
    const Result<HmdProfile> vive = load_hmd_profile("vive");
    ASSERT_TRUE(vive.ok()) << vive.error().message;
    EXPECT_EQ(vive->width, 1344);
    EXPECT_EQ(vive->height, 1512);
    EXPECT_EQ(vive->ipd, 0.064);
    expect_tangents(vive->left, -1.391937, 1.247409, -1.468819, 1.464287);
    expect_tangents(vive->right, -1.246557, 1.398447, -1.465505, 1.472458);
}

TEST(HmdProfile, ViveProReusesViveTangentsAtSetupAResolution) {
    const Result<HmdProfile> vive = load_hmd_profile("vive");
    const Result<HmdProfile> pro = load_hmd_profile("vive-pro");
    ASSERT_TRUE(vive.ok() && pro.ok());
    EXPECT_EQ(pro->width, 2352);
    EXPECT_EQ(pro->height, 2612);
    expect_tangents(pro->left, vive->left.left, vive->left.right, vive->left.down, vive->left.up);
    expect_tangents(pro->right, vive->right.left, vive->right.right, vive->right.down,
                    vive->right.up);
    EXPECT_NE(pro->name.find("no separate calibration"), std::string::npos) << pro->name;
}

TEST(HmdProfile, SymmetricProfilesMatchTheirFieldOfView) {
    const double tan45 = std::tan(45.0 * std::numbers::pi / 180.0);
    const double tan55 = std::tan(55.0 * std::numbers::pi / 180.0);
    const Result<HmdProfile> fov90 = load_hmd_profile("symmetric-90");
    const Result<HmdProfile> fov110 = load_hmd_profile("symmetric-110");
    ASSERT_TRUE(fov90.ok() && fov110.ok());
    for (const rig::Tangents& eye : {fov90->left, fov90->right}) {
        EXPECT_NEAR(eye.right, tan45, 1e-15);
        EXPECT_EQ(eye.left, -eye.right);
        EXPECT_EQ(eye.down, -eye.up);
    }
    for (const rig::Tangents& eye : {fov110->left, fov110->right}) {
        EXPECT_NEAR(eye.right, tan55, 1e-15);
        EXPECT_EQ(eye.left, -eye.right);
        EXPECT_EQ(eye.down, -eye.up);
    }
    EXPECT_EQ(fov110->width, 1024);
    EXPECT_EQ(fov110->height, 1024);
}

// The built-ins are compiled in; they must equal the files a user can read and copy.
TEST(HmdProfile, BuiltinsEqualTheirFiles) {
    const char* source_dir = std::getenv("MONOPLANE_SOURCE_DIR");  // set by ctest
    if (source_dir == nullptr) GTEST_SKIP() << "MONOPLANE_SOURCE_DIR not set (run through ctest)";
    for (const std::string& name : builtin_hmd_names()) {
        const std::filesystem::path file =
            std::filesystem::path(source_dir) / "hmd" / "profiles" / (name + ".toml");
        const Result<HmdProfile> builtin = load_hmd_profile(name);
        const Result<HmdProfile> from_file = load_hmd_profile(file.string());
        ASSERT_TRUE(builtin.ok() && from_file.ok()) << file;
        EXPECT_EQ(builtin->name, from_file->name);
        EXPECT_EQ(builtin->ipd, from_file->ipd);
        EXPECT_EQ(builtin->width, from_file->width);
        EXPECT_EQ(builtin->height, from_file->height);
        for (const auto& [a, b] : {std::pair{builtin->left, from_file->left},
                                   std::pair{builtin->right, from_file->right}}) {
            expect_tangents(a, b.left, b.right, b.down, b.up);
        }
    }
}

TEST(HmdProfile, LoadsFromAFilePath) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "monoplane_hmd_profile_test.toml";
    std::ofstream(path) << mutated("width = 1344", "width = 2000");
    const Result<HmdProfile> profile = load_hmd_profile(path.string());
    std::filesystem::remove(path);
    ASSERT_TRUE(profile.ok()) << profile.error().message;
    EXPECT_EQ(profile->width, 2000);
    EXPECT_EQ(profile->source, path.string());
}

TEST(HmdProfile, ErrorsFromAFileNameThePath) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "monoplane_hmd_profile_bad_test.toml";
    std::ofstream(path) << mutated("ipd = 0.064", "ipd = 64");
    const Result<HmdProfile> profile = load_hmd_profile(path.string());
    std::filesystem::remove(path);
    ASSERT_FALSE(profile.ok());
    EXPECT_EQ(profile.error().message.rfind(path.string() + ":2:", 0), 0u)
        << profile.error().message;
    EXPECT_NE(profile.error().message.find("millimetres"), std::string::npos);
}

TEST(HmdProfile, UnknownNameListsBuiltins) {
    const Result<HmdProfile> profile = load_hmd_profile("oculus-dk0");
    ASSERT_FALSE(profile.ok());
    const std::string& message = profile.error().message;
    EXPECT_NE(message.find("oculus-dk0"), std::string::npos) << message;
    for (const std::string& name : builtin_hmd_names()) {
        EXPECT_NE(message.find(name), std::string::npos) << message;
    }
}

TEST(HmdProfile, DirectoryIsRefused) {
    const Result<HmdProfile> profile =
        load_hmd_profile(std::filesystem::temp_directory_path().string());
    ASSERT_FALSE(profile.ok());
    EXPECT_NE(profile.error().message.find("directory"), std::string::npos);
}

TEST(HmdProfile, ZeroCantIsAccepted) {
    const Result<HmdProfile> profile =
        parse_hmd_profile(mutated("[right]\n", "[right]\ncant_deg = 0\n"), "test.toml");
    ASSERT_TRUE(profile.ok()) << profile.error().message;
    EXPECT_EQ(profile->cant_deg, (std::array<double, 2>{0.0, 0.0}));
}

TEST(HmdProfile, CantIsReadPerEyeAndReachesTheRigInRadians) {
    const Result<HmdProfile> profile =
        parse_hmd_profile(mutated("[right]\n", "[right]\ncant_deg = -2.5\n"), "test.toml");
    ASSERT_TRUE(profile.ok()) << profile.error().message;
    EXPECT_EQ(profile->cant_deg, (std::array<double, 2>{0.0, -2.5}));
    const rig::RigInputs inputs = rig_inputs(*profile, 8.0);
    EXPECT_DOUBLE_EQ(inputs.cant[rig::kRight], -2.5 * 3.14159265358979323846 / 180.0);
    EXPECT_EQ(inputs.cant[rig::kLeft], 0.0);
}

TEST(HmdProfile, TheCantedBuiltinTurnsBothDisplaysOutwards) {
    const Result<HmdProfile> canted = load_hmd_profile("canted-15");
    const Result<HmdProfile> vive = load_hmd_profile("vive");
    ASSERT_TRUE(canted.ok() && vive.ok());
    EXPECT_EQ(canted->cant_deg, (std::array<double, 2>{15.0, -15.0}));
    EXPECT_EQ(canted->left.left, vive->left.left);  // the Vive's frusta, turned
    EXPECT_EQ(canted->right.up, vive->right.up);
    EXPECT_TRUE(rig::build_rig(rig_inputs(*canted, 8.0)).ok());
}

TEST(HmdProfile, IntegerTangentsAreNumbers) {
    const Result<HmdProfile> profile =
        parse_hmd_profile(mutated("tan_up = 1.464287", "tan_up = 1"), "test.toml");
    ASSERT_TRUE(profile.ok()) << profile.error().message;
    EXPECT_EQ(profile->left.up, 1.0);
}

TEST(HmdProfile, AllProblemsAreReportedInDocumentOrder) {
    std::string text = mutated("width = 1344", "width = \"wide\"");
    text.replace(text.find("tan_down = -1.465505"), 20, "tan_down = 1.465505");
    const Result<HmdProfile> profile = parse_hmd_profile(text, "test.toml");
    ASSERT_FALSE(profile.ok());
    const std::string& message = profile.error().message;
    EXPECT_EQ(message.find("test.toml:3:"), 0u) << message;
    EXPECT_NE(message.find("\ntest.toml:16:"), std::string::npos) << message;
}

struct MalformedCase {
    std::string_view what;
    std::string_view from;
    std::string_view to;
    // Each must occur in the message; the key name is the one that matters to a user.
    std::vector<std::string_view> expected;
};

class MalformedProfile : public testing::TestWithParam<MalformedCase> {};

TEST_P(MalformedProfile, IsRefusedNamingSourceAndKey) {
    const MalformedCase& c = GetParam();
    const Result<HmdProfile> profile = parse_hmd_profile(mutated(c.from, c.to), "test.toml");
    ASSERT_FALSE(profile.ok()) << c.what;
    const std::string& message = profile.error().message;
    EXPECT_EQ(message.rfind("test.toml", 0), 0u) << message;
    for (std::string_view expected : c.expected) {
        EXPECT_NE(message.find(expected), std::string::npos)
            << c.what << ": expected \"" << expected << "\" in:\n"
            << message;
    }
}

const MalformedCase kMalformedCases[] = {
    // Missing keys, at the top level and inside an eye.
    {"missing name",
     "name = \"test headset\"\n",
     "",
     {"test.toml: key 'name': required key is missing"}},
    {"missing ipd", "ipd = 0.064\n", "", {"test.toml: key 'ipd': required key is missing"}},
    {"missing width", "width = 1344\n", "", {"test.toml: key 'width': required key is missing"}},
    {"missing tangent", "tan_up = 1.472458\n", "", {"test.toml:12:", "'right.tan_up'"}},
    {"missing eye table", "[right]", "[other]", {"'right'", "'other'"}},
    // Wrong types.
    {"string width", "width = 1344", "width = \"wide\"", {"test.toml:3:", "'width'", "string"}},
    {"fractional height", "height = 1512", "height = 1512.5", {"'height'", "integer"}},
    {"float width", "width = 1344", "width = 1344.0", {"'width'", "integer"}},
    {"string ipd", "ipd = 0.064", "ipd = \"64mm\"", {"'ipd'", "number"}},
    {"numeric name", "name = \"test headset\"", "name = 7", {"'name'", "string"}},
    {"empty name", "name = \"test headset\"", "name = \"\"", {"'name'", "empty"}},
    {"boolean tangent", "tan_left = -1.391937", "tan_left = true", {"'left.tan_left'"}},
    {"eye not a table",
     "[left]\ntan_left = -1.391937\ntan_right = 1.247409\n"
     "tan_up = 1.464287\ntan_down = -1.468819\n",
     "left = 3\n",
     {"'left'", "table"}},
    // Unknown keys, misspelt and foreign.
    {"typo in eye",
     "tan_left = -1.391937",
     "tan_lft = -1.391937",
     {"test.toml:7:", "key 'left.tan_lft': unknown key", "did you mean 'left.tan_left'"}},
    {"typo at top", "ipd = 0.064", "ipd = 0.064\nwidht = 10", {"key 'widht': unknown key"}},
    {"foreign key",
     "ipd = 0.064",
     "ipd = 0.064\nrefresh_hz = 90",
     {"key 'refresh_hz': unknown key", "known keys"}},
    // Non-finite numbers.
    {"nan ipd", "ipd = 0.064", "ipd = nan", {"'ipd'", "finite"}},
    {"infinite tangent",
     "tan_right = 1.398447",
     "tan_right = inf",
     {"'right.tan_right'", "finite"}},
    {"negative infinite tangent",
     "tan_down = -1.468819",
     "tan_down = -inf",
     {"'left.tan_down'", "finite"}},
    // Ranges.
    {"ipd in millimetres", "ipd = 0.064", "ipd = 64", {"'ipd'", "millimetres"}},
    {"negative ipd", "ipd = 0.064", "ipd = -0.01", {"'ipd'", "[0, 0.1]"}},
    {"ipd just above range", "ipd = 0.064", "ipd = 0.1001", {"'ipd'"}},
    {"tiny width", "width = 1344", "width = 8", {"'width'", "[16, 16384]"}},
    {"huge height", "height = 1512", "height = 20000", {"'height'", "[16, 16384]"}},
    {"negative width", "width = 1344", "width = -1344", {"'width'"}},
    // Tangent signs, each named by its key.
    {"left.tan_right negative",
     "tan_right = 1.247409",
     "tan_right = -1.247409",
     {"test.toml:8:", "'left.tan_right'", "positive"}},
    {"left.tan_left positive",
     "tan_left = -1.391937",
     "tan_left = 1.391937",
     {"'left.tan_left'", "negative"}},
    {"OpenVR sign for up",
     "tan_up = 1.472458",
     "tan_up = -1.472458",
     {"'right.tan_up'", "positive", "GetProjectionRaw"}},
    {"OpenVR sign for down",
     "tan_down = -1.465505",
     "tan_down = 1.465505",
     {"'right.tan_down'", "negative"}},
    {"zero tangent", "tan_left = -1.246557", "tan_left = 0.0", {"'right.tan_left'"}},
    // Implausible magnitudes: an angle in degrees instead of its tangent.
    {"degrees for a tangent",
     "tan_right = 1.398447",
     "tan_right = 54.4",
     {"'right.tan_right'", "10"}},
    {"just beyond the bound", "tan_down = -1.468819", "tan_down = -10.01", {"'left.tan_down'"}},
    // Canted displays.
    {"cant beyond 45 degrees",
     "[left]\n",
     "[left]\ncant_deg = 50\n",
     {"test.toml:7:", "'left.cant_deg'", "must not exceed 45"}},
    {"cant not finite", "[right]\n", "[right]\ncant_deg = nan\n", {"'right.cant_deg'"}},
    {"cant as a string", "[left]\n", "[left]\ncant_deg = \"5\"\n", {"'left.cant_deg'", "number"}},
    // TOML syntax errors: file, line, column and the parser's description.
    {"value missing", "width = 1344", "width = ", {"test.toml:3:", "TOML syntax error"}},
    {"duplicate key",
     "height = 1512",
     "height = 1512\nheight = 1600",
     {"test.toml:5:", "TOML syntax error", "height"}},
    {"unterminated string",
     "name = \"test headset\"",
     "name = \"test headset",
     {"test.toml:1:", "TOML syntax error"}},
    {"unclosed table header", "[right]", "[right", {"test.toml:12:", "TOML syntax error"}},
};

INSTANTIATE_TEST_SUITE_P(AllClasses, MalformedProfile, testing::ValuesIn(kMalformedCases),
                         [](const testing::TestParamInfo<MalformedCase>& info) {
                             std::string name;
                             for (char ch : info.param.what) {
                                 name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                             }
                             return name;
                         });

}  // namespace
}  // namespace monoplane::hmd
