// The evidence of imported scenes (docs/scenes.md, "glTF scenes in a study"): SHA-256 digests
// checked against the published FIPS 180-2 example vectors (not against this code's own output;
// the e2e test compares with the `sha256sum` program), which scenes entries are files and where
// they resolve, and the re-reading `study resume` does to find changed or missing files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "study/file_digest.h"
#include "study/scene_files.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

// FIPS 180-2, appendix B: the digests of "abc", of the 448-bit two-block message and of one
// million 'a' (which digest_file reads in several pieces); the empty message's is the well-known
// e3b0c442... (NIST's SHA-256 short-message test vector for Len = 0).
constexpr std::string_view kAbc =
    "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad";
constexpr std::string_view kTwoBlock =
    "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1";
constexpr std::string_view kMillionA =
    "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0";
constexpr std::string_view kEmpty =
    "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855";

class SceneFilesTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::path(::testing::TempDir()) / "scene_files_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path write(const std::string& name, const std::string& bytes) {
        fs::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    }

    fs::path dir_;
};

TEST_F(SceneFilesTest, DigestsMatchThePublishedVectors) {
    const struct {
        std::string bytes;
        std::string_view sha256;
    } cases[] = {
        {"abc", kAbc},
        {"abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq", kTwoBlock},
        {std::string(1'000'000, 'a'), kMillionA},
        {"", kEmpty},
    };
    for (const auto& c : cases) {
        const Result<FileDigest> digest = digest_file(write("message", c.bytes));
        ASSERT_TRUE(digest.ok()) << digest.error().message;
        EXPECT_EQ(digest->sha256, c.sha256) << c.bytes.size() << " bytes";
        EXPECT_EQ(digest->size_bytes, c.bytes.size());
        EXPECT_TRUE(is_sha256_hex(digest->sha256));
    }
}

TEST_F(SceneFilesTest, DigestRefusesMissingFilesAndDirectoriesNamingThem) {
    const Result<FileDigest> missing = digest_file(dir_ / "gone.bin");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find((dir_ / "gone.bin").string() + "' does not exist"),
              std::string::npos)
        << missing.error().message;
    const Result<FileDigest> directory = digest_file(dir_);
    ASSERT_FALSE(directory.ok());
    EXPECT_NE(directory.error().message.find("is not a regular file"), std::string::npos)
        << directory.error().message;
}

TEST(SceneFileForm, HexDigestsAreLowercaseAnd64Long) {
    EXPECT_TRUE(is_sha256_hex(kAbc));
    EXPECT_FALSE(is_sha256_hex(std::string(kAbc).substr(1)));
    std::string upper(kAbc);
    upper[0] = 'B';
    EXPECT_FALSE(is_sha256_hex(upper));
    EXPECT_FALSE(is_sha256_hex(std::string(63, '0') + "g"));
}

TEST(SceneFileForm, NamesEndingInGltfOrGlbAreFilesInAnyCase) {
    for (const char* name : {"room.glb", "models/room.gltf", "ROOM.GLB", "a.GlTf", "/abs/x.glb"})
        EXPECT_TRUE(names_scene_file(name)) << name;
    for (const char* name : {"beams", "room.obj", "room.glb.bak", "glb", "room.gl", ""})
        EXPECT_FALSE(names_scene_file(name)) << name;
}

TEST(SceneFileForm, RelativeEntriesResolveAgainstTheProtocolsFolder) {
    EXPECT_EQ(resolve_scene_file("models/room.glb", "/study/protocols"),
              fs::path("/study/protocols/models/room.glb"));
    EXPECT_EQ(resolve_scene_file("../scenes/./room.gltf", "/study/protocols"),
              fs::path("/study/scenes/room.gltf"));
    EXPECT_EQ(resolve_scene_file("/data/room.glb", "/study/protocols"), fs::path("/data/room.glb"));
    // A relative folder (a protocol named relative to the working directory) becomes absolute.
    EXPECT_EQ(resolve_scene_file("room.glb", "protocols"),
              (fs::current_path() / "protocols/room.glb").lexically_normal());
}

TEST(SceneFileForm, RecordedPathsAreEachScenesOwnFile) {
    const std::vector<SceneFileRecord> records = {
        {"a.gltf", 0, "/d/a.gltf", {1, std::string(kAbc)}},
        {"a.gltf", 1, "/d/a.bin", {2, std::string(kEmpty)}},
        {"b.glb", 0, "/e/b.glb", {3, std::string(kAbc)}},
    };
    const auto paths = recorded_scene_paths(records);
    ASSERT_EQ(paths.size(), 2u);
    EXPECT_EQ(paths.at("a.gltf"), fs::path("/d/a.gltf"));
    EXPECT_EQ(paths.at("b.glb"), fs::path("/e/b.glb"));
}

TEST_F(SceneFilesTest, ChangedAndMissingFilesAreFoundWithBothDigests) {
    const fs::path gltf = write("room.gltf", "abc");
    const fs::path bin = write("room.bin", "");
    const fs::path png = write("room.png", "abc");
    const std::vector<SceneFileRecord> records = {
        {"room.gltf", 0, gltf, {3, std::string(kAbc)}},
        {"room.gltf", 1, bin, {0, std::string(kEmpty)}},
        {"room.gltf", 2, png, {3, std::string(kAbc)}},
    };
    EXPECT_TRUE(changed_scene_files(records).empty());

    write("room.bin", "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq");
    fs::remove(png);
    const std::vector<SceneFileChange> changes = changed_scene_files(records);
    ASSERT_EQ(changes.size(), 2u);
    EXPECT_EQ(changes[0].recorded, records[1]);
    ASSERT_TRUE(changes[0].now.has_value());
    EXPECT_EQ(changes[0].now->sha256, kTwoBlock);
    EXPECT_EQ(changes[0].now->size_bytes, 56u);
    const std::string changed = describe(changes[0]);
    EXPECT_NE(changed.find("scene 'room.gltf': " + bin.string() + " changed"), std::string::npos)
        << changed;
    EXPECT_NE(changed.find("recorded sha256 " + std::string(kEmpty) + " (0 bytes)"),
              std::string::npos)
        << changed;
    EXPECT_NE(changed.find("now sha256 " + std::string(kTwoBlock) + " (56 bytes)"),
              std::string::npos)
        << changed;

    EXPECT_EQ(changes[1].recorded, records[2]);
    EXPECT_FALSE(changes[1].now.has_value());
    const std::string missing = describe(changes[1]);
    EXPECT_NE(missing.find(png.string() + " cannot be read"), std::string::npos) << missing;
    EXPECT_NE(missing.find("does not exist"), std::string::npos) << missing;
    EXPECT_NE(missing.find("recorded sha256 " + std::string(kAbc)), std::string::npos) << missing;
}

// The same bytes again (a tool rewrote the file unchanged) are no change.
TEST_F(SceneFilesTest, RewritingTheSameBytesIsNoChange) {
    const fs::path gltf = write("room.glb", "abc");
    const std::vector<SceneFileRecord> records = {{"room.glb", 0, gltf, {3, std::string(kAbc)}}};
    write("room.glb", "abc");
    EXPECT_TRUE(changed_scene_files(records).empty());
}

}  // namespace
}  // namespace monoplane::study
