// glTF import on real assets: Debian's assimp-testmodels (the Khronos sample models and
// assimp's own broken files, /usr/share/assimp/models). Expected values come from the files'
// JSON, read by hand or with a few lines of Python, never from the loader.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "scenes/generate.h"
#include "scenes/gltf/load_gltf.h"
#include "tests/unit/gltf_scene_checks.h"
#include "tests/unit/gltf_test_files.h"

namespace monoplane::scenes {
namespace {

using testing::quiet;

const std::filesystem::path kModels = MONOPLANE_ASSIMP_MODELS;

class GltfAssets : public ::testing::Test {
  protected:
    void SetUp() override {
        if (!std::filesystem::is_directory(kModels / "glTF2")) {
            FAIL() << kModels / "glTF2"
                   << " is missing: install Debian's assimp-testmodels (scripts/install-deps.sh)";
        }
    }
    static std::filesystem::path model(const std::string& relative) {
        return kModels / "glTF2" / relative;
    }

    static Scene load(const std::string& relative, GltfLoadReport* report = nullptr) {
        Result<Scene> scene = load_gltf_scene(model(relative), quiet(), report);
        EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.error().message);
        if (!scene.ok()) return {};
        testing::expect_well_formed(*scene);
        return std::move(scene).value();
    }
    // The whole message after the path.
    static std::string error(const std::filesystem::path& file) {
        Result<Scene> scene = load_gltf_scene(file, quiet());
        EXPECT_FALSE(scene.ok()) << file;
        if (scene.ok()) return {};
        const std::string& message = scene.error().message;
        EXPECT_EQ(message.rfind(file.string(), 0), 0u) << message;
        return message.substr(file.string().size());
    }
};

// The same box three ways: external .bin and PNG, .glb, everything in data: URIs. 24 vertices,
// 12 triangles, positions in [-0.5, 0.5] turned by a quarter turn about x (the root node's
// matrix), a 211 x 211 logo; the first file's sampler (alone) says wrapS MIRRORED_REPEAT and
// wrapT CLAMP_TO_EDGE.
TEST_F(GltfAssets, BoxTexturedInAllThreeContainersIsTheSameScene) {
    std::vector<std::uint64_t> hashes;
    for (const char* file :
         {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb",
          "BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
        const Scene scene = load(file);
        EXPECT_EQ(scene.name, "BoxTextured");
        EXPECT_EQ(scene.triangle_count(), 12u) << file;
        EXPECT_EQ(scene.bounds.min, glm::vec3(-0.5f)) << file;
        EXPECT_EQ(scene.bounds.max, glm::vec3(0.5f)) << file;
        ASSERT_EQ(scene.textures.size(), 1u) << file;
        EXPECT_EQ(scene.textures[0].width, 211u);
        EXPECT_EQ(scene.textures[0].height, 211u);
        const bool first = hashes.empty();
        EXPECT_EQ(scene.textures[0].wrap_u,
                  first ? TextureWrap::MirroredRepeat : TextureWrap::Repeat);
        EXPECT_EQ(scene.textures[0].wrap_v, first ? TextureWrap::ClampToEdge : TextureWrap::Repeat);
        EXPECT_EQ(scene.textures[0].rgba8_srgb.size(), 211u * 211u * 4u);
        for (const Chunk& chunk : scene.chunks) EXPECT_EQ(chunk.texture, 0);
        hashes.push_back(geometry_hash(scene));
    }
    EXPECT_EQ(hashes[0], hashes[1]);
    EXPECT_EQ(hashes[0], hashes[2]);
}

// The engine: 67 mesh instances of 115 primitives, 121 496 triangles by the accessors' counts
// (some repeat an index and are dropped); its camera (node 81, a matrix) stands at
// (1005.987, 766.317, 953.346) looking along the third column negated, -(0.6247, 0.4685, 0.6247).
TEST_F(GltfAssets, TwoCylinderEngineLoadsWithItsCamera) {
    GltfLoadReport report;
    const Scene scene = load("2CylinderEngine-glTF-Binary/2CylinderEngine.glb", &report);
    EXPECT_EQ(scene.triangle_count() + report.triangles_dropped_degenerate, 121496u);
    EXPECT_GT(scene.chunks.size(), 121496u / kMaxChunkTriangles);
    const rig::Pose& head = scene.viewpoints.front().head;
    EXPECT_NEAR(head.position.x, 1005.987427, 1e-3);
    EXPECT_NEAR(head.position.y, 766.317078, 1e-3);
    EXPECT_NEAR(head.position.z, 953.345581, 1e-3);
    const glm::dvec3 forward = head.orientation * glm::dvec3(0, 0, -1);
    EXPECT_NEAR(forward.x, -0.624695, 1e-5);
    EXPECT_NEAR(forward.y, -0.468521, 1e-5);
    EXPECT_NEAR(forward.z, -0.624695, 1e-5);
}

// Cameras.gltf: camera nodes 1 and 2 at translation (0.5, 0.5, 3), no rotation; node 0's square
// (2 triangles).
TEST_F(GltfAssets, CamerasGiveTheDefaultViewpoint) {
    const Scene scene = load("cameras/Cameras.gltf");
    EXPECT_EQ(scene.triangle_count(), 2u);
    const rig::Pose& head = scene.viewpoints.front().head;
    EXPECT_NEAR(head.position.x, 0.5, 1e-9);
    EXPECT_NEAR(head.position.y, 0.5, 1e-9);
    EXPECT_NEAR(head.position.z, 3.0, 1e-9);
    EXPECT_NEAR(head.orientation.w, 1.0, 1e-12);
}

// The Asset Generator's primitive modes (its README): a unit square in the z = 0 plane facing
// +z, as triangles, strip or fan, with and without indices of each type. Two triangles that tile
// the square: the diagonals cut it into four regions, each triangle of corners covers two, and
// a point inside each region must lie in exactly one triangle.
TEST_F(GltfAssets, PrimitiveModesTileTheSquare) {
    for (const int number : {4, 5, 6, 11, 12, 13, 14, 15}) {
        char name[96];
        std::snprintf(name, sizeof name,
                      "glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_%02d.gltf",
                      number);
        const Scene scene = load(name);
        ASSERT_EQ(scene.triangle_count(), 2u) << name;
        for (const glm::vec2 centre : {glm::vec2(0.3f, 0.1f), glm::vec2(-0.1f, 0.3f),
                                       glm::vec2(-0.3f, -0.1f), glm::vec2(0.1f, -0.3f)}) {
            int inside = 0;
            for (const testing::WorldTriangle& t : testing::triangles_of(scene)) {
                // Counter-clockwise seen from +z: the point is left of all three edges.
                bool left = true;
                for (int k = 0; k < 3; ++k) {
                    const glm::vec3 a = t.p[k];
                    const glm::vec3 b = t.p[(k + 1) % 3];
                    left = left &&
                           (b.x - a.x) * (centre.y - a.y) - (b.y - a.y) * (centre.x - a.x) > 0.0f;
                }
                inside += left;
            }
            EXPECT_EQ(inside, 1) << name << " at " << centre.x << ", " << centre.y;
        }
    }
    for (const int number : {0, 1, 2, 3, 7, 8, 9, 10}) {
        char name[96];
        std::snprintf(name, sizeof name,
                      "glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_%02d.gltf",
                      number);
        EXPECT_EQ(error(model(name)),
                  " has no triangles to draw (only 1 primitive of points or lines)");
    }
}

// Cube.gltf: 36-vertex cubes (12 triangles), their 35-vertex truncations (11 triangles and 2
// left-over indices), and four line primitives, skipped.
TEST_F(GltfAssets, IncorrectVertexArraysDropIncompleteTriangles) {
    GltfLoadReport report;
    const Scene scene = load("IncorrectVertexArrays/Cube.gltf", &report);
    EXPECT_EQ(scene.triangle_count(), 12u + 11u + 12u + 11u);
    EXPECT_EQ(report.indices_dropped_incomplete, 4u);
    EXPECT_EQ(report.primitives_skipped_points_or_lines, 4u);
}

TEST_F(GltfAssets, OtherSampleModelsLoadWellFormed) {
    for (const char* file :
         {"BoxBadNormals-glTF-Binary/BoxBadNormals.glb", "BoxTexcoords-glTF/boxTexcoords.gltf",
          "BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf",
          "ClearCoat-glTF/ClearCoatTest.gltf",
          "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf",
          "issue_3269/texcoord_crash.gltf", "simple_skin/simple_skin.gltf",
          "textureTransform/TextureTransformTest.gltf"}) {
        SCOPED_TRACE(file);
        const Scene scene = load(file);
        EXPECT_GT(scene.triangle_count(), 0u);
    }
}

TEST_F(GltfAssets, BrokenFilesGiveOneClearError) {
    struct Case {
        std::string file;
        std::string message;  // after the path
    };
    const std::vector<Case> cases = {
        {"RecursiveNodes/RecursiveNodes.gltf",
         ": the node hierarchy has a cycle (0 -> 1 -> 0): node 0 is its own ancestor, but glTF "
         "nodes "
         "form trees"},
        {"MissingBin/BoxTextured.gltf",
         ": buffer 0: file \"BoxTextured0.bin\" not found in " + model("MissingBin").string()},
        {"IndexOutOfRange/IndexOutOfRange.gltf",
         ": accessor 0 (indices of mesh 'Mesh' primitive 0): index 255 at position 0 is out of "
         "range "
         "(the primitive has 24 vertices)"},
        {"IndexOutOfRange/AllIndicesOutOfRange.gltf",
         ": accessor 0 (indices of mesh 'Mesh' primitive 0): index 65535 at position 0 is out of "
         "range (the primitive has 24 vertices)"},
        {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
         ": accessor 2 (POSITION of mesh 'Mesh' primitive 0): element 0 is not finite (-inf)"},
        {"wrongTypes/badArray.gltf", ": meshes[0].primitives must be an array, not an object"},
        {"wrongTypes/badExtension.gltf",
         ": materials[0].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform "
         "must be an object, not a string"},
        // normalTexture {"scale": "not a number"} also lacks its required index, found first.
        {"wrongTypes/badNumber.gltf", ": materials[0].normalTexture.index is missing"},
        {"wrongTypes/badObject.gltf",
         ": materials[0].pbrMetallicRoughness must be an object, not an array"},
        {"wrongTypes/badString.gltf", ": scenes[0].name must be a string, not an integer"},
        {"wrongTypes/badUint.gltf",
         ": materials[0].pbrMetallicRoughness.baseColorTexture.index must be a non-negative "
         "integer, "
         "not -1"},
        {"SchemaFailures/sceneWrongType.gltf",
         ": scene must be a non-negative integer, not a string"},
        {"TestNoRootNode/NoScene.gltf", ": scene is 0, but the file has 0 scenes"},
        {"TestNoRootNode/SceneWithoutNodes.gltf",
         " has no triangles to draw (its scene has no meshes)"},
        {"draco/2CylinderEngine.gltf",
         ": the file requires the extension KHR_draco_mesh_compression (compressed geometry this "
         "build cannot decode), which this loader does not support"},
        {"BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf",
         ": the file requires the extension KHR_technique_webgl (an extension this loader does not "
         "know), which this loader does not support"},
    };
    for (const Case& c : cases) EXPECT_EQ(error(model(c.file)), c.message) << c.file;
}

// assimp's glTF 1.0 models: text and binary.
TEST_F(GltfAssets, GltfOneIsRefusedWithAReason) {
    EXPECT_EQ(
        error(kModels / "glTF/BoxTextured-glTF/BoxTextured.gltf"),
        ": glTF 1.0 is not supported (asset.version is \"1.0\"): only glTF 2.0 is, convert the "
        "file to glTF 2.0");
    EXPECT_EQ(error(kModels / "glTF/BoxTextured-glTF-Binary/BoxTextured.glb"),
              " is binary glTF version 1 (glTF 1.0), which is not supported: convert the file to "
              "glTF 2.0");
    EXPECT_EQ(error(kModels / "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf"),
              ": glTF 1.0 is not supported (no asset.version, and meshes or nodes are objects, not "
              "arrays): convert the file to glTF 2.0");
}

}  // namespace
}  // namespace monoplane::scenes
