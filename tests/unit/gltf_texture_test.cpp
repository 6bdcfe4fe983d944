// Base-colour textures of imported scenes: kept (image, texture coordinates, chunk texture) for
// the renderer, which samples them (tests/gpu/textured_scene_test.cpp); the vertex albedo holds
// only the base-colour factor and vertex colour, which the texture multiplies in the shader.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "scenes/gltf/load_gltf.h"
#include "tests/unit/gltf_scene_checks.h"
#include "tests/unit/gltf_test_files.h"
#include "tests/unit/png_bytes.h"

namespace monoplane::scenes {
namespace {

using monoplane::testing::png_bytes;
using nlohmann::json;
using testing::quiet;
using testing::TestGltf;

void write_bytes(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
}

// A triangle with texture coordinates and material 0, whose base colour is texture 0.
void add_textured_triangle(TestGltf& file, const std::vector<glm::vec2>& uv, float z = 0.0f,
                           int material = 0) {
    const int positions = file.add_positions({{0, 0, z}, {1, 0, z}, {0, 1, z}});
    const int texcoords = file.add_vec2(uv);
    file.add_node({{"mesh", file.add_mesh({{"POSITION", positions}, {"TEXCOORD_0", texcoords}}, -1,
                                          4, material)}});
}

json textured_material(int texture, std::vector<double> factor = {1, 1, 1, 1}) {
    return {{"pbrMetallicRoughness",
             {{"baseColorTexture", {{"index", texture}}}, {"baseColorFactor", factor}}}};
}

const std::vector<unsigned char> kOrange = {255, 128, 0, 255, 255, 128, 0, 255,
                                            255, 128, 0, 255, 255, 128, 0, 255};

TEST(GltfTexture, ExternalPngIsKeptWithItsCoordinates) {
    const auto dir = testing::test_directory("texture_png");
    write_bytes(dir / "orange.png", png_bytes(2, 2, kOrange));
    TestGltf file;
    file.json["images"] = {{{"uri", "orange.png"}}};
    file.json["textures"] = {{{"source", 0}}};
    file.json["materials"] = {textured_material(0, {0.5, 1, 1, 1})};
    const std::vector<glm::vec2> uv = {{0.1f, 0.2f}, {0.9f, 0.2f}, {0.1f, 0.8f}};
    add_textured_triangle(file, uv);
    file.write_gltf(dir / "textured.gltf");

    Result<Scene> loaded = load_gltf_scene(dir / "textured.gltf", quiet());
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    const Scene& scene = *loaded;
    testing::expect_well_formed(scene);
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.textures[0].width, 2u);
    EXPECT_EQ(scene.textures[0].height, 2u);
    EXPECT_EQ(scene.textures[0].rgba8_srgb, kOrange);  // sRGB as in the file
    EXPECT_EQ(scene.textures[0].wrap_u, TextureWrap::Repeat);
    ASSERT_EQ(scene.chunks.size(), 1u);
    EXPECT_EQ(scene.chunks[0].texture, 0);
    ASSERT_EQ(scene.texcoords.size(), scene.vertices.size());
    for (std::size_t i = 0; i < scene.vertices.size(); ++i) {
        const glm::vec3 p = scene.vertices[i].position;
        const glm::vec2 expected = p.x > 0.5f ? uv[1] : (p.y > 0.5f ? uv[2] : uv[0]);
        EXPECT_EQ(scene.texcoords[i], expected);
        // The factor only (0.5 packs to 128): the renderer multiplies the texture in.
        EXPECT_EQ(scene.vertices[i].albedo_rgba8, 0xffffff80u)
            << std::hex << scene.vertices[i].albedo_rgba8;
    }
}

TEST(GltfTexture, TheSamplersWrapModesAreKept) {
    struct Case {
        int wrap_s, wrap_t;
        TextureWrap u, v;
    };
    const std::vector<Case> cases = {
        {33071, 10497, TextureWrap::ClampToEdge, TextureWrap::Repeat},
        {33648, 33071, TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge},
    };
    const auto dir = testing::test_directory("wrap_modes");
    write_bytes(dir / "ramp.png", png_bytes(2, 1, {0, 0, 0, 255, 255, 255, 255, 255}));
    for (const Case& c : cases) {
        TestGltf file;
        file.json["images"] = {{{"uri", "ramp.png"}}};
        file.json["samplers"] = {{{"wrapS", c.wrap_s}, {"wrapT", c.wrap_t}}};
        file.json["textures"] = {{{"source", 0}, {"sampler", 0}}};
        file.json["materials"] = {textured_material(0)};
        add_textured_triangle(file, {{0.25f, 0.5f}, {0.75f, 0.5f}, {0.0f, 0.5f}});
        file.write_glb(dir / "ramp.glb");
        Result<Scene> scene = load_gltf_scene(dir / "ramp.glb", quiet());
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        EXPECT_EQ(scene->textures[0].wrap_u, c.u) << c.wrap_s;
        EXPECT_EQ(scene->textures[0].wrap_v, c.v) << c.wrap_t;
        for (const Vertex& v : scene->vertices) EXPECT_EQ(v.albedo_rgba8, 0xffffffffu);
    }
}

// The same image embedded in a .glb buffer view, and as a data: URI in a .gltf.
TEST(GltfTexture, EmbeddedImages) {
    const auto dir = testing::test_directory("texture_embedded");
    const std::vector<unsigned char> image = png_bytes(2, 2, kOrange);
    {
        TestGltf file;
        file.json["images"] = {
            {{"bufferView", file.add_view(image.data(), image.size())}, {"mimeType", "image/png"}}};
        file.json["textures"] = {{{"source", 0}}};
        file.json["materials"] = {textured_material(0)};
        add_textured_triangle(file, {{0, 0}, {1, 0}, {0, 1}});
        file.write_glb(dir / "view.glb");
    }
    {
        TestGltf file;
        file.json["images"] = {{{"uri", "data:image/png;base64," + testing::base64(image)}}};
        file.json["textures"] = {{{"source", 0}}};
        file.json["materials"] = {textured_material(0)};
        add_textured_triangle(file, {{0, 0}, {1, 0}, {0, 1}});
        file.write_gltf(dir / "data_uri.gltf");
    }
    for (const char* name : {"view.glb", "data_uri.gltf"}) {
        Result<Scene> scene = load_gltf_scene(dir / name, quiet());
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        ASSERT_EQ(scene->textures.size(), 1u) << name;
        EXPECT_EQ(scene->textures[0].rgba8_srgb, kOrange) << name;
        for (const Vertex& v : scene->vertices) EXPECT_EQ(v.albedo_rgba8, 0xffffffffu) << name;
    }
}

// Two textures on two overlapping triangles: two chunks, one texture each.
TEST(GltfTexture, ChunksNeverMixTextures) {
    const auto dir = testing::test_directory("texture_mix");
    write_bytes(dir / "orange.png", png_bytes(2, 2, kOrange));
    write_bytes(dir / "white.png", png_bytes(1, 1, {255, 255, 255, 255}));
    TestGltf file;
    file.json["images"] = {{{"uri", "orange.png"}}, {{"uri", "white.png"}}};
    file.json["textures"] = {{{"source", 0}}, {{"source", 1}}};
    file.json["materials"] = {textured_material(0), textured_material(1)};
    add_textured_triangle(file, {{0, 0}, {1, 0}, {0, 1}}, 0.0f, 0);
    add_textured_triangle(file, {{0, 0}, {1, 0}, {0, 1}}, 0.1f, 1);
    add_textured_triangle(file, {{0, 0}, {1, 0}, {0, 1}}, 0.2f, 0);
    file.write_gltf(dir / "mix.gltf");
    Result<Scene> scene = load_gltf_scene(dir / "mix.gltf", quiet());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    testing::expect_well_formed(*scene);
    ASSERT_EQ(scene->textures.size(), 2u);
    ASSERT_EQ(scene->chunks.size(), 2u);
    for (const testing::WorldTriangle& t : testing::triangles_of(*scene)) {
        const bool white = std::abs(t.p[0].z - 0.1f) < 1e-6f;
        const int texture = white ? 1 : 0;
        EXPECT_EQ(t.texture, texture);
        EXPECT_EQ(scene->textures[static_cast<std::size_t>(texture)].width, white ? 1u : 2u);
        EXPECT_EQ(t.albedo[0], 0xffffffffu);
    }
}

TEST(GltfTexture, PrimitiveWithoutItsTexcoordsIsDrawnUntextured) {
    const auto dir = testing::test_directory("texture_no_uv");
    write_bytes(dir / "orange.png", png_bytes(2, 2, kOrange));
    TestGltf file;
    file.json["images"] = {{{"uri", "orange.png"}}};
    file.json["textures"] = {{{"source", 0}}};
    file.json["materials"] = {textured_material(0, {0.5, 0.5, 0.5, 1})};
    file.json["extensionsUsed"] = {"KHR_texture_transform"};
    const int positions = file.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    file.add_node({{"mesh", file.add_mesh({{"POSITION", positions}}, -1, 4, 0)}});
    file.write_gltf(dir / "no_uv.gltf");
    GltfLoadReport report;
    Result<Scene> scene = load_gltf_scene(dir / "no_uv.gltf", quiet(), &report);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(report.textures_without_texcoords, 1u);
    EXPECT_TRUE(scene->textures.empty());
    EXPECT_TRUE(scene->texcoords.empty());
    EXPECT_EQ(scene->chunks[0].texture, -1);
    for (const Vertex& v : scene->vertices) EXPECT_EQ(v.albedo_rgba8, 0xff808080u);
    const std::vector<std::string> expected = {
        "drew 1 primitive without its base-colour texture (no TEXCOORD_n for it)",
        "ignores extensions KHR_texture_transform"};
    EXPECT_EQ(report.warnings, expected);
}

TEST(GltfTexture, BadImagesAreErrors) {
    const auto dir = testing::test_directory("texture_bad");
    write_bytes(dir / "orange.png", png_bytes(2, 2, kOrange));
    write_bytes(dir / "garbage.png", {'n', 'o', 't', ' ', 'a', ' ', 'p', 'n', 'g'});
    struct Case {
        std::string uri;
        std::uint64_t max_texels;
        std::string message;
    };
    const std::vector<Case> cases = {
        {"orange.png", 3,
         "texture 0 (image 0 'orange.png') has 2 x 2 texels, more than the limit of 3"},
        {"missing.png", 1u << 20,
         "texture 0 (image 0 'missing.png'): file not found in " + dir.string()},
        {"garbage.png", 1u << 20,
         "texture 0 (image 0 'garbage.png') is not a PNG or JPEG image that can be decoded"},
    };
    for (const Case& c : cases) {
        TestGltf file;
        file.json["images"] = {{{"uri", c.uri}}};
        file.json["textures"] = {{{"source", 0}}};
        file.json["materials"] = {textured_material(0)};
        add_textured_triangle(file, {{0, 0}, {1, 0}, {0, 1}});
        file.write_gltf(dir / "bad.gltf");
        GltfLoadOptions options = quiet();
        options.max_texture_texels = c.max_texels;
        Result<Scene> scene = load_gltf_scene(dir / "bad.gltf", options);
        ASSERT_FALSE(scene.ok()) << c.uri;
        EXPECT_EQ(scene.error().message.rfind(
                      (dir / "bad.gltf").string() + ": mesh 0 primitive 0: " + c.message, 0),
                  0u)
            << scene.error().message;
    }
}

}  // namespace
}  // namespace monoplane::scenes
