// glTF's material.alphaMode and alphaCutoff on import (scenes::AlphaMode): what the chunks
// carry, how chunks are grouped, the vertex albedo's alpha, the errors, and what levels of detail
// and the geometry hash make of masked and blended chunks. The renderer's side is tested on the
// GPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "scenes/chunk_builder.h"
#include "scenes/generate.h"
#include "scenes/gltf/load_gltf.h"
#include "scenes/icosphere.h"
#include "scenes/lod_chain.h"
#include "tests/unit/gltf_scene_checks.h"
#include "tests/unit/gltf_test_files.h"
#include "tests/unit/png_bytes.h"

namespace monoplane::scenes {
namespace {

using nlohmann::json;
using testing::quiet;
using testing::TestGltf;

// A material with this base-colour factor and, unless empty, alphaMode; a negative cutoff leaves
// alphaCutoff out.
json alpha_material(const std::string& mode, double cutoff = -1.0,
                    std::vector<double> factor = {1, 1, 1, 1}, const std::string& name = "") {
    json material = {{"pbrMetallicRoughness", {{"baseColorFactor", factor}}}};
    if (!mode.empty()) material["alphaMode"] = mode;
    if (cutoff >= 0.0) material["alphaCutoff"] = cutoff;
    if (!name.empty()) material["name"] = name;
    return material;
}

// The primitive of a triangle at depth z with this material (-1: none).
json triangle_primitive(TestGltf& file, float z, int material) {
    const int positions = file.add_positions({{0, 0, z}, {1, 0, z}, {0, 1, z}});
    json primitive = {{"attributes", {{"POSITION", positions}}}, {"mode", 4}};
    if (material >= 0) primitive["material"] = material;
    return primitive;
}

// One triangle with material 0 (or none for -1).
void add_triangle(TestGltf& file, int material = 0, float z = 0.0f) {
    file.json["meshes"].push_back(
        {{"primitives", json::array({triangle_primitive(file, z, material)})}});
    file.add_node({{"mesh", static_cast<int>(file.json["meshes"].size()) - 1}});
}

// One mesh whose primitives are one triangle each, primitive i with materials[i], at z = -i.
void add_mesh_of_triangles(TestGltf& file, const std::vector<int>& materials) {
    json primitives = json::array();
    for (std::size_t i = 0; i < materials.size(); ++i) {
        primitives.push_back(triangle_primitive(file, -static_cast<float>(i), materials[i]));
    }
    file.json["meshes"].push_back({{"primitives", primitives}, {"name", "Mixed"}});
    file.add_node({{"mesh", static_cast<int>(file.json["meshes"].size()) - 1}});
}

class GltfAlphaMode : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = testing::test_directory(
            std::string("alpha_") +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    }
    Scene load(TestGltf& file, const std::string& name = "alpha.gltf",
               GltfLoadReport* report = nullptr) {
        file.write_gltf(dir_ / name);
        Result<Scene> scene = load_gltf_scene(dir_ / name, quiet(), report);
        EXPECT_TRUE(scene.ok()) << scene.error().message;
        if (!scene.ok()) return Scene{};
        testing::expect_well_formed(*scene);
        return std::move(scene).value();
    }
    std::string error_of(TestGltf& file) {
        file.write_gltf(dir_ / "bad.gltf");
        Result<Scene> scene = load_gltf_scene(dir_ / "bad.gltf", quiet());
        EXPECT_FALSE(scene.ok());
        if (scene.ok()) return {};
        const std::string& message = scene.error().message;
        EXPECT_EQ(message.rfind((dir_ / "bad.gltf").string(), 0), 0u) << message;
        return message;
    }
    std::filesystem::path dir_;
};

TEST_F(GltfAlphaMode, MaskWithAnExplicitCutoff) {
    TestGltf file;
    file.json["materials"] = {alpha_material("MASK", 0.3)};
    add_triangle(file);
    GltfLoadReport report;
    const Scene scene = load(file, "alpha.gltf", &report);
    ASSERT_EQ(scene.chunks.size(), 1u);
    EXPECT_EQ(scene.chunks[0].alpha_mode, AlphaMode::kMask);
    EXPECT_FLOAT_EQ(scene.chunks[0].alpha_cutoff, 0.3f);
    // Drawn as authored now: no warning about alpha modes.
    EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
}

TEST_F(GltfAlphaMode, MaskWithoutCutoffUsesHalf) {
    TestGltf file;
    file.json["materials"] = {alpha_material("MASK")};
    add_triangle(file);
    const Scene scene = load(file);
    ASSERT_EQ(scene.chunks.size(), 1u);
    EXPECT_EQ(scene.chunks[0].alpha_mode, AlphaMode::kMask);
    EXPECT_FLOAT_EQ(scene.chunks[0].alpha_cutoff, 0.5f);
}

TEST_F(GltfAlphaMode, MaskCutoffsOfZeroAndAboveOneAreKept) {
    TestGltf file;
    file.json["materials"] = {alpha_material("MASK", 0.0), alpha_material("MASK", 1.5)};
    add_triangle(file, 0, 0.0f);
    add_triangle(file, 1, -1.0f);
    const Scene scene = load(file);
    ASSERT_EQ(scene.chunks.size(), 2u);
    std::vector<float> cutoffs;
    for (const Chunk& chunk : scene.chunks) {
        EXPECT_EQ(chunk.alpha_mode, AlphaMode::kMask);
        cutoffs.push_back(chunk.alpha_cutoff);
    }
    std::sort(cutoffs.begin(), cutoffs.end());
    EXPECT_FLOAT_EQ(cutoffs[0], 0.0f);
    EXPECT_FLOAT_EQ(cutoffs[1], 1.5f);
}

TEST_F(GltfAlphaMode, BlendIgnoresTheCutoff) {
    TestGltf file;
    file.json["materials"] = {alpha_material("BLEND", 0.2, {0.2, 0.4, 0.6, 0.25})};
    add_triangle(file);
    GltfLoadReport report;
    const Scene scene = load(file, "alpha.gltf", &report);
    ASSERT_EQ(scene.chunks.size(), 1u);
    EXPECT_EQ(scene.chunks[0].alpha_mode, AlphaMode::kBlend);
    EXPECT_FLOAT_EQ(scene.chunks[0].alpha_cutoff, 0.5f);  // the specification: ignored
    EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
}

TEST_F(GltfAlphaMode, OpaqueExplicitAbsentOrWithoutMaterial) {
    TestGltf file;
    file.json["materials"] = {alpha_material("OPAQUE", 0.9, {1, 1, 1, 0.3}), alpha_material("")};
    add_triangle(file, 0, 0.0f);
    add_triangle(file, 1, -1.0f);
    add_triangle(file, -1, -2.0f);  // glTF's default material
    const Scene scene = load(file);
    ASSERT_EQ(scene.chunks.size(), 1u);  // one look: untextured and opaque
    EXPECT_EQ(scene.chunks[0].alpha_mode, AlphaMode::kOpaque);
    EXPECT_FLOAT_EQ(scene.chunks[0].alpha_cutoff, 0.5f);
    EXPECT_EQ(scene.chunks[0].index_count, 9u);
}

TEST_F(GltfAlphaMode, MixedMaterialsInOneMeshGiveSeparateChunks) {
    TestGltf file;
    file.json["materials"] = {alpha_material("OPAQUE"), alpha_material("MASK", 0.25),
                              alpha_material("MASK", 0.75), alpha_material("BLEND"),
                              alpha_material("MASK", 0.25, {1, 0, 0, 1})};
    // Primitives: opaque, mask 0.25, mask 0.75, blend, mask 0.25 again (another material, the
    // same look: it shares the first mask's chunk), opaque again.
    add_mesh_of_triangles(file, {0, 1, 2, 3, 4, 0});
    const Scene scene = load(file);
    struct Expected {
        AlphaMode mode;
        float cutoff;
        std::uint32_t triangles;
    };
    std::vector<Expected> found;
    for (const Chunk& chunk : scene.chunks) {
        found.push_back({chunk.alpha_mode, chunk.alpha_cutoff, chunk.index_count / 3});
    }
    ASSERT_EQ(found.size(), 4u);
    const auto count = [&](AlphaMode mode, float cutoff) {
        return std::count_if(found.begin(), found.end(), [&](const Expected& e) {
            return e.mode == mode && e.cutoff == cutoff;
        });
    };
    EXPECT_EQ(count(AlphaMode::kOpaque, 0.5f), 1);
    EXPECT_EQ(count(AlphaMode::kMask, 0.25f), 1);
    EXPECT_EQ(count(AlphaMode::kMask, 0.75f), 1);
    EXPECT_EQ(count(AlphaMode::kBlend, 0.5f), 1);
    for (const Expected& e : found) {
        const bool two =
            e.mode == AlphaMode::kOpaque || (e.mode == AlphaMode::kMask && e.cutoff == 0.25f);
        EXPECT_EQ(e.triangles, two ? 2u : 1u);
    }
    // The triangles kept their places: the blended one is primitive 3's, at z = -3.
    for (const Chunk& chunk : scene.chunks) {
        if (chunk.alpha_mode != AlphaMode::kBlend) continue;
        EXPECT_FLOAT_EQ(chunk.bounds.min.z, -3.0f);
        EXPECT_FLOAT_EQ(chunk.bounds.max.z, -3.0f);
    }
}

// The renderer orders blended chunks back to front as wholes, so two blended primitives (panes of
// glass) never share a chunk, even with one material; masked ones of one look do.
TEST_F(GltfAlphaMode, BlendedPrimitivesNeverShareAChunk) {
    TestGltf file;
    file.json["materials"] = {alpha_material("BLEND"), alpha_material("MASK")};
    add_mesh_of_triangles(file, {0, 0, 0, 1, 1});
    add_triangle(file, 0, -7.0f);  // a second instance of the same material
    const Scene scene = load(file);
    std::vector<float> blend_depths;
    std::uint32_t mask_chunks = 0;
    for (const Chunk& chunk : scene.chunks) {
        if (chunk.alpha_mode == AlphaMode::kBlend) {
            EXPECT_EQ(chunk.index_count, 3u);
            EXPECT_EQ(chunk.bounds.min.z, chunk.bounds.max.z);
            blend_depths.push_back(chunk.bounds.min.z);
        } else {
            EXPECT_EQ(chunk.alpha_mode, AlphaMode::kMask);
            EXPECT_EQ(chunk.index_count, 6u);
            ++mask_chunks;
        }
    }
    std::sort(blend_depths.begin(), blend_depths.end());
    EXPECT_EQ(blend_depths, (std::vector<float>{-7.0f, -2.0f, -1.0f, 0.0f}));
    EXPECT_EQ(mask_chunks, 1u);
}

TEST_F(GltfAlphaMode, TextureAndAlphaModeSplitChunksTogether) {
    TestGltf file;
    const std::vector<unsigned char> white = {255, 255, 255, 255};
    monoplane::testing::write_png(dir_ / "white.png", 1, 1, white);
    file.json["images"] = {{{"uri", "white.png"}}};
    file.json["textures"] = {{{"source", 0}}};
    json textured_mask = alpha_material("MASK", 0.4);
    textured_mask["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    json textured_opaque = alpha_material("OPAQUE");
    textured_opaque["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    file.json["materials"] = {textured_mask, textured_opaque, alpha_material("MASK", 0.4)};
    for (int m = 0; m < 3; ++m) {
        const float z = -static_cast<float>(m);
        const int positions = file.add_positions({{0, 0, z}, {1, 0, z}, {0, 1, z}});
        const int uv = file.add_vec2({{0, 0}, {1, 0}, {0, 1}});
        file.add_node(
            {{"mesh", file.add_mesh({{"POSITION", positions}, {"TEXCOORD_0", uv}}, -1, 4, m)}});
    }
    const Scene scene = load(file);
    ASSERT_EQ(scene.chunks.size(), 3u);
    for (const Chunk& chunk : scene.chunks) {
        ASSERT_EQ(chunk.index_count, 3u);
        const float z = chunk.bounds.min.z;
        if (z == 0.0f) {
            EXPECT_EQ(chunk.texture, 0);
            EXPECT_EQ(chunk.alpha_mode, AlphaMode::kMask);
            EXPECT_FLOAT_EQ(chunk.alpha_cutoff, 0.4f);
        } else if (z == -1.0f) {
            EXPECT_EQ(chunk.texture, 0);
            EXPECT_EQ(chunk.alpha_mode, AlphaMode::kOpaque);
        } else {
            EXPECT_EQ(z, -2.0f);
            EXPECT_EQ(chunk.texture, -1);
            EXPECT_EQ(chunk.alpha_mode, AlphaMode::kMask);
            EXPECT_FLOAT_EQ(chunk.alpha_cutoff, 0.4f);
        }
    }
}

TEST_F(GltfAlphaMode, UnknownAlphaModeIsAnErrorNamingItAndTheMaterial) {
    TestGltf file;
    file.json["materials"] = {alpha_material("OPAQUE"),
                              alpha_material("ADDITIVE", -1.0, {1, 1, 1, 1}, "Glow")};
    add_triangle(file, 1);
    const std::string message = error_of(file);
    EXPECT_NE(message.find("material 1 'Glow'"), std::string::npos) << message;
    EXPECT_NE(message.find("alphaMode 'ADDITIVE' is not OPAQUE, MASK or BLEND"), std::string::npos)
        << message;
}

TEST_F(GltfAlphaMode, LowerCaseAlphaModeIsAnError) {
    TestGltf file;
    file.json["materials"] = {alpha_material("mask")};
    add_triangle(file);
    const std::string message = error_of(file);
    EXPECT_NE(message.find("material 0: alphaMode 'mask' is not OPAQUE, MASK or BLEND"),
              std::string::npos)
        << message;
}

TEST_F(GltfAlphaMode, NegativeCutoffIsAnError) {
    TestGltf file;
    file.json["materials"] = {alpha_material("MASK", -1.0, {1, 1, 1, 1}, "Leaf")};
    file.json["materials"][0]["alphaCutoff"] = -0.25;
    add_triangle(file);
    const std::string message = error_of(file);
    EXPECT_NE(message.find("material 0 'Leaf': alphaCutoff -0.25 is negative"), std::string::npos)
        << message;
    // The schema's minimum holds whatever the mode.
    TestGltf blend;
    blend.json["materials"] = {alpha_material("BLEND")};
    blend.json["materials"][0]["alphaCutoff"] = -1;
    add_triangle(blend);
    const std::string blend_message = error_of(blend);
    EXPECT_NE(blend_message.find("material 0: alphaCutoff -1 is negative"), std::string::npos)
        << blend_message;
}

std::uint32_t alpha_byte(std::uint32_t rgba8) {
    return rgba8 >> 24;
}

TEST_F(GltfAlphaMode, VertexAlbedoCarriesTheFactorsAndColoursAlpha) {
    TestGltf file;
    file.json["materials"] = {alpha_material("BLEND", -1.0, {0.5, 0.25, 1.0, 0.25})};
    // Triangle 0: no COLOR_0; triangle 1: COLOR_0 VEC4 with alphas 0.5, 1, 0; triangle 2: COLOR_0
    // VEC3 (opaque colour: the factor's alpha stays).
    add_triangle(file, 0, 0.0f);
    {
        const int positions = file.add_positions({{0, 0, -1}, {1, 0, -1}, {0, 1, -1}});
        const int colours = file.add_accessor(
            std::vector<float>{1, 1, 1, 0.5f, 1, 1, 1, 1, 1, 1, 1, 0}, testing::kFloat, "VEC4", 3);
        file.add_node(
            {{"mesh", file.add_mesh({{"POSITION", positions}, {"COLOR_0", colours}}, -1, 4, 0)}});
    }
    {
        const int positions = file.add_positions({{0, 0, -2}, {1, 0, -2}, {0, 1, -2}});
        const int colours = file.add_accessor(std::vector<float>{1, 1, 1, 1, 1, 1, 1, 1, 1},
                                              testing::kFloat, "VEC3", 3);
        file.add_node(
            {{"mesh", file.add_mesh({{"POSITION", positions}, {"COLOR_0", colours}}, -1, 4, 0)}});
    }
    const Scene scene = load(file);
    ASSERT_EQ(scene.chunks.size(), 3u);  // blended: one chunk per primitive instance
    std::vector<std::uint32_t> at_depth[3];
    for (const testing::WorldTriangle& t : testing::triangles_of(scene)) {
        const int depth = static_cast<int>(-t.p[0].z);
        ASSERT_GE(depth, 0);
        ASSERT_LT(depth, 3);
        for (int k = 0; k < 3; ++k) {
            // The colour keeps the factor's channels (R 0.5 -> 128, G 0.25 -> 64, B 1 -> 255).
            EXPECT_EQ(t.albedo[k] & 0xffffffu, 128u | (64u << 8) | (255u << 16));
            const glm::vec3& p = t.p[k];
            std::uint32_t expected = 64;  // 0.25 * 255
            if (depth == 1) {
                // COLOR_0 alphas 0.5 (the origin), 1 (x = 1), 0 (y = 1), times 0.25.
                expected = p.x > 0.5f ? 64u : (p.y > 0.5f ? 0u : 32u);
            }
            EXPECT_EQ(alpha_byte(t.albedo[k]), expected) << "depth " << depth << " corner " << k;
        }
    }
}

TEST_F(GltfAlphaMode, OpaqueVerticesKeepTheirAlphaToo) {
    // Opaque chunks ignore alpha, but the vertex carries it all the same: the albedo is what the
    // file says.
    TestGltf file;
    file.json["materials"] = {alpha_material("OPAQUE", -1.0, {1, 1, 1, 0.6})};
    add_triangle(file);
    const Scene scene = load(file);
    ASSERT_FALSE(scene.vertices.empty());
    for (const Vertex& v : scene.vertices) EXPECT_EQ(alpha_byte(v.albedo_rgba8), 153u);
}

// An icosphere of 5,120 triangles as one chunk: opaque it simplifies into several levels.
Scene sphere_chunk(AlphaMode mode) {
    const IcosphereMesh mesh = make_icosphere(4);
    ChunkBuilder builder(kMaxChunkTriangles);
    builder.begin_piece();
    for (const glm::vec3& d : mesh.directions) {
        builder.add_vertex({d, d, pack_rgba8(0.5f, 0.5f, 0.5f, 0.5f), pack_material({})});
    }
    for (const auto& t : mesh.triangles) builder.add_triangle(t[0], t[1], t[2]);
    Scene scene;
    builder.build_into(scene);
    for (Chunk& chunk : scene.chunks) {
        chunk.alpha_mode = mode;
        chunk.alpha_cutoff = 0.3f;
    }
    return scene;
}

TEST(GltfAlphaModeLod, MaskedAndBlendedChunksKeepOnlyFullDetail) {
    const Scene opaque = sphere_chunk(AlphaMode::kOpaque);
    ASSERT_EQ(opaque.chunks.size(), 1u);
    EXPECT_GE(build_lod_chain(opaque).chunks.at(0).level_count, 4u);
    for (const AlphaMode mode : {AlphaMode::kMask, AlphaMode::kBlend}) {
        const Scene scene = sphere_chunk(mode);
        const LodChain chain = build_lod_chain(scene);
        ASSERT_EQ(chain.chunks.size(), 1u);
        EXPECT_EQ(chain.chunks[0].level_count, 0u);
        EXPECT_EQ(chain.chunks[0].first_level, 0u);
        EXPECT_TRUE(chain.levels.empty());
        EXPECT_TRUE(chain.indices.empty());
    }
}

TEST(GltfAlphaModeLod, OnlyTheNonOpaqueChunksOfAMixedSceneLoseTheirLevels) {
    // Two spheres, the second masked: the first keeps its chain, in its place.
    Scene scene = sphere_chunk(AlphaMode::kOpaque);
    const Scene masked = sphere_chunk(AlphaMode::kMask);
    Chunk second = masked.chunks[0];
    second.first_index += static_cast<std::uint32_t>(scene.indices.size());
    second.vertex_offset += static_cast<std::int32_t>(scene.vertices.size());
    scene.indices.insert(scene.indices.end(), masked.indices.begin(), masked.indices.end());
    scene.vertices.insert(scene.vertices.end(), masked.vertices.begin(), masked.vertices.end());
    scene.chunks.push_back(second);
    const LodChain alone = build_lod_chain(sphere_chunk(AlphaMode::kOpaque));
    const LodChain chain = build_lod_chain(scene);
    ASSERT_EQ(chain.chunks.size(), 2u);
    EXPECT_EQ(chain.chunks[0].level_count, alone.chunks[0].level_count);
    EXPECT_EQ(chain.chunks[1].level_count, 0u);
    EXPECT_EQ(chain.indices, alone.indices);
}

TEST_F(GltfAlphaMode, HashDiffersWhenACutoffChanges) {
    const auto scene_with = [&](double cutoff, const std::string& name) {
        TestGltf file;
        file.json["materials"] = {alpha_material("MASK", cutoff)};
        add_triangle(file);
        return load(file, name);
    };
    const Scene a = scene_with(0.3, "a.gltf");
    const Scene again = scene_with(0.3, "again.gltf");
    const Scene b = scene_with(0.4, "b.gltf");
    EXPECT_EQ(geometry_hash(a), geometry_hash(again));
    EXPECT_NE(geometry_hash(a), geometry_hash(b));
    // So does the mode, with the same cut-off.
    Scene blended = a;
    blended.chunks[0].alpha_mode = AlphaMode::kBlend;
    EXPECT_NE(geometry_hash(blended), geometry_hash(a));
}

TEST(GltfAlphaModeHash, OpaqueScenesHashNoAlphaFields) {
    // A scene without masked or blended chunks hashes as before alpha modes: the cut-off field
    // (unused when opaque) changes nothing, so procedural and opaque hashes stay what they were.
    Scene scene = generate_scene(SceneId::Spheres, Detail::Test);
    const std::uint64_t before = geometry_hash(scene);
    for (Chunk& chunk : scene.chunks) chunk.alpha_cutoff = 0.9f;
    EXPECT_EQ(geometry_hash(scene), before);
    scene.chunks[0].alpha_mode = AlphaMode::kMask;
    EXPECT_NE(geometry_hash(scene), before);
}

}  // namespace
}  // namespace monoplane::scenes
