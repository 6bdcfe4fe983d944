// GltfLoadReport::files_read: every file a load read, which a study session digests as evidence
// of what it showed (docs/scenes.md, "glTF scenes in a study"): the .gltf or .glb first, then its
// external buffers and images in the order read, each once; data: URIs and a .glb's own BIN
// chunk read no other file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "scenes/gltf/load_gltf.h"
#include "tests/unit/gltf_test_files.h"

namespace monoplane::scenes {
namespace {

namespace fs = std::filesystem;
using testing::quiet;
using testing::TestGltf;

// One triangle; `uv` adds texture coordinates (for a textured material).
TestGltf triangle(bool uv = false) {
    TestGltf file;
    const int positions = file.add_positions({{0, 0, -2}, {1, 0, -2}, {0, 1, -2}});
    nlohmann::json attributes = {{"POSITION", positions}};
    if (uv) attributes["TEXCOORD_0"] = file.add_vec2({{0, 0}, {1, 0}, {0, 1}});
    file.add_node({{"mesh", file.add_mesh(attributes, -1, 4, uv ? 0 : -1)}});
    return file;
}

// A 1 x 1 PNG, 8-bit greyscale, one black pixel: the signature and the IHDR, IDAT (zlib) and
// IEND chunks of the PNG specification with their CRCs.
const std::vector<unsigned char> kOnePixelPng = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
    0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00,
    0x00, 0x3a, 0x7e, 0x9b, 0x55, 0x00, 0x00, 0x00, 0x0a, 0x49, 0x44, 0x41, 0x54, 0x78,
    0x9c, 0x63, 0x60, 0x00, 0x00, 0x00, 0x02, 0x00, 0x01, 0x48, 0xaf, 0xa4, 0x71, 0x00,
    0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

TEST(GltfFilesRead, AGltfWithABufferAndAnImageListsAllThreeOnce) {
    const fs::path dir = testing::test_directory("files_read_external");
    TestGltf file = triangle(true);
    {
        std::ofstream png(dir / "albedo.png", std::ios::binary);
        png.write(reinterpret_cast<const char*>(kOnePixelPng.data()),
                  static_cast<std::streamsize>(kOnePixelPng.size()));
    }
    file.json["images"] = {{{"uri", "albedo.png"}}, {{"uri", "./albedo.png"}}};
    file.json["textures"] = {{{"source", 0}}, {{"source", 1}}};
    file.json["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    file.write_gltf_with_bin(dir / "room.gltf", "room.bin");

    GltfLoadReport report;
    const Result<Scene> scene = load_gltf_scene(dir / "." / "room.gltf", quiet(), &report);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    // The second image names the first's file again: one entry.
    EXPECT_EQ(report.files_read,
              (std::vector<fs::path>{dir / "room.gltf", dir / "room.bin", dir / "albedo.png"}));
}

TEST(GltfFilesRead, EmbeddedDataAndGlbReadOnlyTheFileItself) {
    const fs::path dir = testing::test_directory("files_read_embedded");
    TestGltf file = triangle();
    file.write_gltf(dir / "embedded.gltf");
    file.write_glb(dir / "packed.glb");
    GltfLoadReport report;
    ASSERT_TRUE(load_gltf_scene(dir / "embedded.gltf", quiet(), &report).ok());
    EXPECT_EQ(report.files_read, std::vector<fs::path>{dir / "embedded.gltf"});
    ASSERT_TRUE(load_gltf_scene(dir / "packed.glb", quiet(), &report).ok());
    EXPECT_EQ(report.files_read, std::vector<fs::path>{dir / "packed.glb"});
}

}  // namespace
}  // namespace monoplane::scenes
