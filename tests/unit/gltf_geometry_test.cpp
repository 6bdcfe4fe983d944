// glTF import on files the tests write themselves: primitive modes, index types, node transforms
// (positions and normals against values worked out by hand), mirrored nodes, generated normals,
// materials, viewpoints, scene selection, instancing and chunking.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scenes/generate.h"
#include "scenes/gltf/load_gltf.h"
#include "tests/unit/gltf_scene_checks.h"
#include "tests/unit/gltf_test_files.h"

namespace monoplane::scenes {
namespace {

using nlohmann::json;
using testing::has_triangle;
using testing::quiet;
using testing::TestGltf;
using testing::triangles_of;

Scene load_ok(const std::filesystem::path& file, GltfLoadOptions options = quiet(),
              GltfLoadReport* report = nullptr) {
    Result<Scene> scene = load_gltf_scene(file, options, report);
    EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.error().message);
    if (!scene.ok()) return {};
    return std::move(scene).value();
}

// One counter-clockwise triangle (seen from +z) at the origin, no normals, no material.
TEST(GltfGeometry, OneTriangleWithGeneratedNormalAndDefaults) {
    const auto dir = testing::test_directory("one_triangle");
    TestGltf file;
    const int positions = file.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    file.add_node({{"mesh", file.add_mesh({{"POSITION", positions}})}});
    file.write_gltf(dir / "triangle.gltf");

    GltfLoadReport report;
    const Scene scene = load_ok(dir / "triangle.gltf", quiet(), &report);
    testing::expect_well_formed(scene);
    EXPECT_EQ(scene.id, SceneId::Imported);
    EXPECT_EQ(scene.name, "triangle");
    EXPECT_EQ(scene_name(scene.id), "imported");
    ASSERT_EQ(scene.triangle_count(), 1u);
    EXPECT_TRUE(has_triangle(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
    for (const Vertex& v : scene.vertices) {
        EXPECT_TRUE(testing::near(v.normal, {0, 0, 1}));
        EXPECT_EQ(v.albedo_rgba8, 0xffffffffu);  // glTF's default material is white
        // ...with roughness 1 and metallic 1, which the renderer approximates with specular 0.5.
        EXPECT_EQ(v.material_packed, pack_material({1.0f, 0.5f, 0}));
    }
    EXPECT_EQ(scene.bounds.min, glm::vec3(0, 0, 0));
    EXPECT_EQ(scene.bounds.max, glm::vec3(1, 1, 0));
    EXPECT_TRUE(scene.textures.empty());
    EXPECT_TRUE(scene.texcoords.empty());
    EXPECT_EQ(report.normals_generated, 3u);
    ASSERT_EQ(scene.viewpoints.size(), 4u);
    EXPECT_EQ(scene.viewpoints[0].name, "default");
    EXPECT_NE(scene.find_viewpoint("bench-forward"), nullptr);
    EXPECT_NE(scene.find_viewpoint("bench-overview"), nullptr);
    EXPECT_NE(scene.find_viewpoint("bench-side"), nullptr);
}

// Strip v0..v4 (glTF 3.7.2.1): triangles (v0 v1 v2), (v2 v1 v3), (v2 v3 v4), all
// counter-clockwise seen from +z for these positions.
TEST(GltfGeometry, TriangleStripBecomesAList) {
    const auto dir = testing::test_directory("strip");
    TestGltf file;
    const std::vector<glm::vec3> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 2, 0}};
    file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_positions(v)}}, -1, 5)}});
    file.write_gltf(dir / "strip.gltf");
    const Scene scene = load_ok(dir / "strip.gltf");
    testing::expect_well_formed(scene);
    ASSERT_EQ(scene.triangle_count(), 3u);
    EXPECT_TRUE(has_triangle(scene, v[0], v[1], v[2]));
    EXPECT_TRUE(has_triangle(scene, v[2], v[1], v[3]));
    EXPECT_TRUE(has_triangle(scene, v[2], v[3], v[4]));
    for (const Vertex& vertex : scene.vertices)
        EXPECT_TRUE(testing::near(vertex.normal, {0, 0, 1}));
}

// Fan around v0: (v1 v2 v0), (v2 v3 v0); indexed, with a repeated index that adds a degenerate
// triangle (dropped) and a list's incomplete tail elsewhere.
TEST(GltfGeometry, TriangleFanBecomesAListAndDegenerateTrianglesAreDropped) {
    const auto dir = testing::test_directory("fan");
    TestGltf file;
    const std::vector<glm::vec3> v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const int positions = file.add_positions(v);
    // 0 1 2 3 3: the last fan triangle (v3 v3 v0) has no area.
    const int indices = file.add_indices({0, 1, 2, 3, 3}, testing::kUnsignedShort);
    file.add_node({{"mesh", file.add_mesh({{"POSITION", positions}}, indices, 6)}});
    file.write_gltf(dir / "fan.gltf");
    GltfLoadReport report;
    const Scene scene = load_ok(dir / "fan.gltf", quiet(), &report);
    testing::expect_well_formed(scene);
    ASSERT_EQ(scene.triangle_count(), 2u);
    EXPECT_TRUE(has_triangle(scene, v[1], v[2], v[0]));
    EXPECT_TRUE(has_triangle(scene, v[2], v[3], v[0]));
    EXPECT_EQ(report.triangles_dropped_degenerate, 1u);
}

TEST(GltfGeometry, ListTailOfFewerThanThreeIndicesIsDropped) {
    const auto dir = testing::test_directory("tail");
    TestGltf file;
    const int positions = file.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int indices = file.add_indices({0, 1, 2, 0, 1}, testing::kUnsignedByte);
    file.add_node({{"mesh", file.add_mesh({{"POSITION", positions}}, indices)}});
    file.write_gltf(dir / "tail.gltf");
    GltfLoadReport report;
    const Scene scene = load_ok(dir / "tail.gltf", quiet(), &report);
    EXPECT_EQ(scene.triangle_count(), 1u);
    EXPECT_EQ(report.indices_dropped_incomplete, 2u);
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_EQ(report.warnings[0], "dropped 2 indices that complete no triangle");
}

class GltfIndexType : public ::testing::TestWithParam<int> {};

// A unit square as two triangles, whatever the index component type.
TEST_P(GltfIndexType, IndexedSquare) {
    const auto dir = testing::test_directory("index_" + std::to_string(GetParam()));
    TestGltf file;
    const std::vector<glm::vec3> v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const int positions = file.add_positions(v);
    const int indices = file.add_indices({0, 1, 2, 0, 2, 3}, GetParam());
    file.add_node({{"mesh", file.add_mesh({{"POSITION", positions}}, indices)}});
    file.write_glb(dir / "square.glb");
    const Scene scene = load_ok(dir / "square.glb");
    testing::expect_well_formed(scene);
    ASSERT_EQ(scene.triangle_count(), 2u);
    EXPECT_TRUE(has_triangle(scene, v[0], v[1], v[2]));
    EXPECT_TRUE(has_triangle(scene, v[0], v[2], v[3]));
}
INSTANTIATE_TEST_SUITE_P(IndexTypes, GltfIndexType,
                         ::testing::Values(testing::kUnsignedByte, testing::kUnsignedShort,
                                           testing::kUnsignedInt));

// parent: translation (10, 0, 0), rotation +90 degrees about y; child: translation (0, 1, 0),
// scale 2. World = T(10,0,0) R_y(90) T(0,1,0) S(2); R_y(90) takes (x, y, z) to (z, y, -x).
//   (0,0,0) -> S (0,0,0) -> T (0,1,0) -> R (0,1,0)  -> T (10,1,0)
//   (1,0,0) -> S (2,0,0) -> T (2,1,0) -> R (0,1,-2) -> T (10,1,-2)
//   (0,1,0) -> S (0,2,0) -> T (0,3,0) -> R (0,3,0)  -> T (10,3,0)
TEST(GltfGeometry, NodeHierarchyWithTrsTransforms) {
    const auto dir = testing::test_directory("hierarchy");
    TestGltf file;
    const int mesh =
        file.add_mesh({{"POSITION", file.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});
    const double s = std::sin(std::numbers::pi / 4);
    file.add_node({{"translation", {10, 0, 0}}, {"rotation", {0, s, 0, s}}, {"children", {1}}});
    file.add_node({{"translation", {0, 1, 0}}, {"scale", {2, 2, 2}}, {"mesh", mesh}}, false);
    file.write_gltf(dir / "hierarchy.gltf");
    const Scene scene = load_ok(dir / "hierarchy.gltf");
    testing::expect_well_formed(scene);
    ASSERT_EQ(scene.triangle_count(), 1u);
    EXPECT_TRUE(has_triangle(scene, {10, 1, 0}, {10, 1, -2}, {10, 3, 0}, 1e-5f));
    // The face normal, +z in the mesh, turned by R_y(90): +x.
    for (const Vertex& v : scene.vertices) EXPECT_TRUE(testing::near(v.normal, {1, 0, 0}));
}

// A column-major matrix: translation (5, 6, 7) in elements 12-14.
TEST(GltfGeometry, NodeMatrixIsColumnMajor) {
    const auto dir = testing::test_directory("matrix");
    TestGltf file;
    const int mesh =
        file.add_mesh({{"POSITION", file.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});
    file.add_node({{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1}}, {"mesh", mesh}});
    file.write_gltf(dir / "matrix.gltf");
    const Scene scene = load_ok(dir / "matrix.gltf");
    EXPECT_TRUE(has_triangle(scene, {5, 6, 7}, {6, 6, 7}, {5, 7, 7}));
}

// The triangle (1,0,0) (0,1,0) (0,0,1) lies in the plane x + y + z = 1, normal (1,1,1)/sqrt(3)
// (given in the file). Scaled by (2, 1, 1) it lies in x/2 + y + z = 1: normal (0.5, 1, 1)
// normalised, (1, 2, 2) / 3, which is what the inverse transpose diag(1/2, 1, 1) gives.
TEST(GltfGeometry, NormalsTransformByTheInverseTranspose) {
    const auto dir = testing::test_directory("inverse_transpose");
    TestGltf file;
    const float n = 1.0f / std::sqrt(3.0f);
    const int positions = file.add_positions({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    const int normals = file.add_positions({{n, n, n}, {n, n, n}, {n, n, n}});
    file.add_node({{"scale", {2, 1, 1}},
                   {"mesh", file.add_mesh({{"POSITION", positions}, {"NORMAL", normals}})}});
    file.write_gltf(dir / "scaled.gltf");
    GltfLoadReport report;
    const Scene scene = load_ok(dir / "scaled.gltf", quiet(), &report);
    testing::expect_well_formed(scene);
    EXPECT_TRUE(has_triangle(scene, {2, 0, 0}, {0, 1, 0}, {0, 0, 1}));
    for (const Vertex& v : scene.vertices) {
        EXPECT_TRUE(testing::near(v.normal, glm::vec3(1, 2, 2) / 3.0f)) << v.normal.x;
    }
    EXPECT_EQ(report.normals_generated, 0u);
}

// Mirrored in x (scale -1, 1, 1), the triangle (0,0,0) (1,0,0) (0,1,0) becomes (0,0,0) (-1,0,0)
// (0,1,0), clockwise seen from +z; its normal (0,0,1) stays (0,0,1). The loader must reverse
// the winding: the triangle is (0,0,0) (0,1,0) (-1,0,0), counter-clockwise about +z.
TEST(GltfGeometry, MirroredNodeKeepsCounterClockwiseWinding) {
    for (const bool with_normals : {true, false}) {
        const auto dir = testing::test_directory(with_normals ? "mirror_n" : "mirror");
        TestGltf file;
        json attributes = {{"POSITION", file.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}};
        if (with_normals)
            attributes["NORMAL"] = file.add_positions({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
        file.add_node({{"scale", {-1, 1, 1}}, {"mesh", file.add_mesh(attributes)}});
        file.write_gltf(dir / "mirror.gltf");
        const Scene scene = load_ok(dir / "mirror.gltf");
        testing::expect_well_formed(scene);
        EXPECT_TRUE(has_triangle(scene, {0, 0, 0}, {0, 1, 0}, {-1, 0, 0})) << with_normals;
        for (const Vertex& v : scene.vertices) EXPECT_TRUE(testing::near(v.normal, {0, 0, 1}));
    }
}

// glTF's doubleSided: the back of the triangle is a triangle of its own, wound the other way
// about the opposite normal (so back-face culling keeps exactly one of the two from any side);
// a single-sided material keeps one triangle. Counted against the triangle limit as two.
TEST(GltfGeometry, DoubleSidedMaterialsGetBackFaces) {
    for (const bool double_sided : {true, false}) {
        const auto dir = testing::test_directory(double_sided ? "two_sided" : "one_sided");
        TestGltf file;
        file.json["materials"] = {{{"doubleSided", double_sided}}};
        const int positions = file.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        file.add_node({{"mesh", file.add_mesh({{"POSITION", positions}}, -1, 4, 0)}});
        file.write_gltf(dir / "sides.gltf");
        const Scene scene = load_ok(dir / "sides.gltf");
        testing::expect_well_formed(scene);
        ASSERT_EQ(scene.triangle_count(), double_sided ? 2u : 1u);
        EXPECT_TRUE(has_triangle(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
        EXPECT_EQ(has_triangle(scene, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}), double_sided);
        for (const testing::WorldTriangle& t : testing::triangles_of(scene)) {
            const glm::vec3 face = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
            for (const glm::vec3& n : t.n) EXPECT_TRUE(testing::near(n, glm::normalize(face)));
        }
        if (double_sided) {
            GltfLoadOptions limited = quiet();
            limited.max_triangles = 1;
            Result<Scene> refused = load_gltf_scene(dir / "sides.gltf", limited);
            ASSERT_FALSE(refused.ok());
            EXPECT_NE(refused.error().message.find("has 2 triangles"), std::string::npos)
                << refused.error().message;
        }
    }
}

// An octahedron with shared vertices: each vertex touches four faces of equal area whose normals
// (+-1, +-1, +-1)/sqrt(3) sum to its own direction, so the generated normal is the vertex's
// position.
TEST(GltfGeometry, GeneratedNormalsOfAnOctahedronPointOutwards) {
    const auto dir = testing::test_directory("octahedron");
    TestGltf file;
    const std::vector<glm::vec3> v = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                      {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    // Counter-clockwise seen from outside, e.g. (+x, +y, +z): cross((-1,1,0), (-1,0,1)) = (1,1,1).
    const std::vector<std::uint32_t> faces = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                              2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    file.add_node(
        {{"mesh", file.add_mesh({{"POSITION", file.add_positions(v)}}, file.add_indices(faces))}});
    file.write_gltf(dir / "octahedron.gltf");
    const Scene scene = load_ok(dir / "octahedron.gltf");
    testing::expect_well_formed(scene);
    ASSERT_EQ(scene.triangle_count(), 8u);
    for (const Vertex& vertex : scene.vertices) {
        EXPECT_TRUE(testing::near(vertex.normal, vertex.position, 1e-5f));
    }
}

// Two triangles sharing the edge (0,0,0)-(0,1,0): A = (0,0,0) (2,0,0) (0,1,0) has cross product
// (0,0,2), B = (0,0,0) (0,1,0) (0,0,1) has (1,0,0). Area-weighted, the shared vertices get
// (1,0,2)/sqrt(5); the others their own face's normal.
TEST(GltfGeometry, GeneratedNormalsAreAreaWeighted) {
    const auto dir = testing::test_directory("area_weighted");
    TestGltf file;
    const std::vector<glm::vec3> v = {{0, 0, 0}, {0, 1, 0}, {2, 0, 0}, {0, 0, 1}};
    file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_positions(v)}},
                                          file.add_indices({0, 2, 1, 0, 1, 3}))}});
    file.write_gltf(dir / "roof.gltf");
    const Scene scene = load_ok(dir / "roof.gltf");
    testing::expect_well_formed(scene);
    const glm::vec3 shared = glm::vec3(1, 0, 2) / std::sqrt(5.0f);
    for (const Vertex& vertex : scene.vertices) {
        if (testing::near(vertex.position, v[0]) || testing::near(vertex.position, v[1])) {
            EXPECT_TRUE(testing::near(vertex.normal, shared));
        } else if (testing::near(vertex.position, v[2])) {
            EXPECT_TRUE(testing::near(vertex.normal, {0, 0, 1}));
        } else {
            EXPECT_TRUE(testing::near(vertex.normal, {1, 0, 0}));
        }
    }
}

// Flat normals, as the glTF specification asks: every triangle gets its own three vertices.
TEST(GltfGeometry, FlatGeneratedNormalsUnweldVertices) {
    const auto dir = testing::test_directory("flat");
    TestGltf file;
    const std::vector<glm::vec3> v = {{0, 0, 0}, {0, 1, 0}, {2, 0, 0}, {0, 0, 1}};
    file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_positions(v)}},
                                          file.add_indices({0, 2, 1, 0, 1, 3}))}});
    file.write_gltf(dir / "roof.gltf");
    GltfLoadOptions options = quiet();
    options.generated_normals = GeneratedNormals::Flat;
    const Scene scene = load_ok(dir / "roof.gltf", options);
    testing::expect_well_formed(scene);
    EXPECT_EQ(scene.vertices.size(), 6u);
    for (const testing::WorldTriangle& t : triangles_of(scene)) {
        const glm::vec3 expected = t.p[0].z == 0 && t.p[1].z == 0 && t.p[2].z == 0
                                       ? glm::vec3(0, 0, 1)
                                       : glm::vec3(1, 0, 0);
        for (const glm::vec3& n : t.n) EXPECT_TRUE(testing::near(n, expected));
    }
}

// Degenerate normals: a zero normal in the file is replaced by the generated one; a sheet whose
// two sides share vertices (normals cancel) and a zero-area triangle still get unit normals.
TEST(GltfGeometry, DegenerateNormalsGetUnitReplacements) {
    const auto dir = testing::test_directory("degenerate_normals");
    TestGltf file;
    const int positions = file.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int zero_normals = file.add_positions({{0, 0, 0}, {0, 0, 1}, {0, 0, 0}});
    file.add_node({{"mesh", file.add_mesh({{"POSITION", positions}, {"NORMAL", zero_normals}})}});
    const int sheet = file.add_positions({{0, 0, 5}, {1, 0, 5}, {0, 1, 5}});
    file.add_node(
        {{"mesh", file.add_mesh({{"POSITION", sheet}}, file.add_indices({0, 1, 2, 0, 2, 1}))}});
    const int line =
        file.add_positions({{0, 0, 9}, {1, 0, 9}, {2, 0, 9}, {0, 0, 10}, {1, 0, 10}, {0, 1, 10}});
    file.add_node({{"mesh", file.add_mesh({{"POSITION", line}})}});
    file.write_gltf(dir / "degenerate.gltf");
    GltfLoadReport report;
    const Scene scene = load_ok(dir / "degenerate.gltf", quiet(), &report);
    testing::expect_well_formed(scene);
    EXPECT_EQ(scene.triangle_count(), 5u);
    for (const Vertex& v : scene.vertices) {
        if (v.position.z == 0.0f) {
            EXPECT_TRUE(testing::near(v.normal, {0, 0, 1}));
        }
    }
    EXPECT_EQ(report.normals_generated, 2u + 3u + 6u);
}

// baseColorFactor (0.5, 0.25, 1, 1) is linear and lands in albedo_rgba8 as round(255 c):
// 128, 64, 255, 255; roughness 0.3 -> round(76.5) = 77; metallic 0 -> specular 0.04 -> 10.
// COLOR_0 (normalized unsigned bytes) multiplies: (255, 0, 255, 255) turns green to 0.
TEST(GltfGeometry, BaseColourFactorVertexColourAndRoughness) {
    const auto dir = testing::test_directory("material");
    TestGltf file;
    file.json["materials"] = {{{"pbrMetallicRoughness",
                                {{"baseColorFactor", {0.5, 0.25, 1.0, 1.0}},
                                 {"roughnessFactor", 0.3},
                                 {"metallicFactor", 0.0}}}}};
    const int positions = file.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    file.add_node({{"mesh", file.add_mesh({{"POSITION", positions}}, -1, 4, 0)}});
    const int positions2 = file.add_positions({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}});
    const std::vector<std::uint8_t> colours = {255, 0,   255, 255, 255, 0,
                                               255, 255, 255, 0,   255, 255};
    const int colour = file.add_accessor(colours, testing::kUnsignedByte, "VEC4", 3, true);
    file.add_node(
        {{"mesh", file.add_mesh({{"POSITION", positions2}, {"COLOR_0", colour}}, -1, 4, 0)}});
    file.write_glb(dir / "material.glb");
    const Scene scene = load_ok(dir / "material.glb");
    for (const Vertex& v : scene.vertices) {
        const std::uint32_t expected = v.position.z == 0.0f ? 0xffff4080u : 0xffff0080u;
        EXPECT_EQ(v.albedo_rgba8, expected) << std::hex << v.albedo_rgba8;
        const Material material = unpack_material(v.material_packed);
        EXPECT_EQ(v.material_packed & 0xffu, 77u);
        EXPECT_EQ((v.material_packed >> 8) & 0xffu, 10u);
        EXPECT_EQ(material.pattern, 0);
    }
}

// Cameras: the first camera node's world pose. Node translation (1, 2, 3), rotation +90 degrees
// about y: the head sits at (1, 2, 3) looking down -x (R_y(90) turns -z into -x).
TEST(GltfGeometry, DefaultViewpointIsTheFirstCamera) {
    const auto dir = testing::test_directory("camera");
    TestGltf file;
    file.json["cameras"] = {
        {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}}};
    file.add_node(
        {{"mesh",
          file.add_mesh({{"POSITION", file.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}})}});
    const double s = std::sin(std::numbers::pi / 4);
    file.add_node({{"camera", 0}, {"translation", {1, 2, 3}}, {"rotation", {0, s, 0, s}}});
    file.write_gltf(dir / "camera.gltf");
    const Scene scene = load_ok(dir / "camera.gltf");
    const rig::Pose& head = scene.viewpoints.front().head;
    EXPECT_EQ(scene.viewpoints.front().name, "default");
    EXPECT_NEAR(head.position.x, 1.0, 1e-9);
    EXPECT_NEAR(head.position.y, 2.0, 1e-9);
    EXPECT_NEAR(head.position.z, 3.0, 1e-9);
    const glm::dvec3 forward = head.orientation * glm::dvec3(0, 0, -1);
    EXPECT_NEAR(forward.x, -1.0, 1e-9);
    EXPECT_NEAR(forward.y, 0.0, 1e-9);
    EXPECT_NEAR(forward.z, 0.0, 1e-9);
}

// An object (a unit cube, centre at the origin) is framed from outside: bounding sphere radius
// sqrt(3)/2 = 0.866025, at distance r / sin(35 deg) = 1.509869, from +z and 20 degrees up:
// (0, 1.509869 sin 20, 1.509869 cos 20) = (0, 0.516406, 1.418813), pitched 20 degrees down.
TEST(GltfGeometry, DefaultViewpointFramesAnObject) {
    const auto dir = testing::test_directory("object_view");
    TestGltf file;
    const std::vector<glm::vec3> v = {
        {-0.5f, -0.5f, -0.5f}, {0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}};
    file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_positions(v)}})}});
    file.write_gltf(dir / "object.gltf");
    const Scene scene = load_ok(dir / "object.gltf");
    const rig::Pose& head = scene.viewpoints.front().head;
    EXPECT_NEAR(head.position.x, 0.0, 1e-6);
    EXPECT_NEAR(head.position.y, 0.516406, 1e-5);
    EXPECT_NEAR(head.position.z, 1.418813, 1e-5);
    const glm::dvec3 forward = head.orientation * glm::dvec3(0, 0, -1);
    EXPECT_NEAR(forward.y, -std::sin(20.0 * std::numbers::pi / 180), 1e-9);
    EXPECT_NEAR(forward.x, 0.0, 1e-9);
}

// A 10 m x 10 m floor is a place to stand: 1.7 m above its lowest point, 1 m inside its +z edge,
// looking down -z.
TEST(GltfGeometry, DefaultViewpointStandsInAWalkableScene) {
    const auto dir = testing::test_directory("walkable");
    TestGltf file;
    const std::vector<glm::vec3> v = {{-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0.1f, -5}};
    file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_positions(v)}},
                                          file.add_indices({0, 1, 2, 0, 2, 3}))}});
    file.write_gltf(dir / "floor.gltf");
    const Scene scene = load_ok(dir / "floor.gltf");
    testing::expect_well_formed(scene);
    const rig::Pose& head = scene.viewpoints.front().head;
    EXPECT_NEAR(head.position.x, 0.0, 1e-9);
    EXPECT_NEAR(head.position.y, 1.7, 1e-9);
    EXPECT_NEAR(head.position.z, 4.0, 1e-9);
    EXPECT_NEAR(head.orientation.w, 1.0, 1e-12);
    // Triangles face up (+y): counter-clockwise seen from above.
    for (const Vertex& vertex : scene.vertices) EXPECT_GT(vertex.normal.y, 0.99f);
}

// A 10 m cube, wound counter-clockwise seen from outside (a solid, like a large engine block) or
// from inside (a room). Its walkable standing spot (1.7 m above the floor, 1 m inside the +z
// wall) lies inside both: in the room it is open space and the participant stands there; in the
// solid every ray meets a face from behind, so the object is framed from outside instead
// (bounding sphere radius 5 sqrt(3) = 8.660254 at r / sin 35 deg = 15.098689 from its centre).
TEST(GltfGeometry, DefaultViewpointNeverStandsInsideASolid) {
    for (const bool room : {true, false}) {
        const auto dir = testing::test_directory(room ? "room" : "solid");
        TestGltf file;
        const std::vector<glm::vec3> v = {{-5, 0, -5}, {5, 0, -5}, {5, 10, -5}, {-5, 10, -5},
                                          {-5, 0, 5},  {5, 0, 5},  {5, 10, 5},  {-5, 10, 5}};
        // Outward counter-clockwise faces of the cube.
        std::vector<std::uint32_t> faces = {0, 3, 2, 0, 2, 1, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                            3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5};
        if (room) {
            for (std::size_t t = 0; t < faces.size(); t += 3) std::swap(faces[t + 1], faces[t + 2]);
        }
        file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_positions(v)}},
                                              file.add_indices(faces))}});
        file.write_gltf(dir / "cube.gltf");
        const Scene scene = load_ok(dir / "cube.gltf");
        const rig::Pose& head = scene.viewpoints.front().head;
        if (room) {
            EXPECT_NEAR(head.position.y, 1.7, 1e-9);
            EXPECT_NEAR(head.position.z, 4.0, 1e-9);
        } else {
            const double distance = 5.0 * std::sqrt(3.0) / std::sin(35.0 * std::numbers::pi / 180);
            const double angle = 20.0 * std::numbers::pi / 180;
            EXPECT_NEAR(head.position.y, 5.0 + distance * std::sin(angle), 1e-5);
            EXPECT_NEAR(head.position.z, distance * std::cos(angle), 1e-5);
        }
    }
}

// `scene` picks the scene; without it the first scene; without scenes every root node.
TEST(GltfGeometry, SceneSelection) {
    const auto dir = testing::test_directory("scene_choice");
    TestGltf file;
    const int near =
        file.add_mesh({{"POSITION", file.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});
    const int far =
        file.add_mesh({{"POSITION", file.add_positions({{0, 0, 9}, {1, 0, 9}, {0, 1, 9}})}});
    file.add_node({{"mesh", near}}, false);
    file.add_node({{"mesh", far}}, false);
    file.json["scenes"] = {{{"nodes", {0}}}, {{"nodes", {1}}}};
    file.json["scene"] = 1;
    file.write_gltf(dir / "second.gltf");
    EXPECT_EQ(load_ok(dir / "second.gltf").bounds.min.z, 9.0f);
    file.json.erase("scene");
    file.write_gltf(dir / "first.gltf");
    EXPECT_EQ(load_ok(dir / "first.gltf").bounds.max.z, 0.0f);
    file.json.erase("scenes");
    file.write_gltf(dir / "roots.gltf");
    const Scene roots = load_ok(dir / "roots.gltf");
    EXPECT_EQ(roots.triangle_count(), 2u);
}

// One mesh, three nodes: three copies at their translations.
TEST(GltfGeometry, MeshesAreInstancedPerNode) {
    const auto dir = testing::test_directory("instances");
    TestGltf file;
    const int mesh =
        file.add_mesh({{"POSITION", file.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});
    for (const int x : {0, 10, 20}) file.add_node({{"mesh", mesh}, {"translation", {x, 0, 0}}});
    file.write_glb(dir / "instances.glb");
    const Scene scene = load_ok(dir / "instances.glb");
    testing::expect_well_formed(scene);
    ASSERT_EQ(scene.triangle_count(), 3u);
    for (const float x : {0.0f, 10.0f, 20.0f}) {
        EXPECT_TRUE(has_triangle(scene, {x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}));
    }
}

// Sparse accessors: positions from a base view with two elements replaced.
TEST(GltfGeometry, SparseAccessorsSubstituteElements) {
    const auto dir = testing::test_directory("sparse");
    TestGltf file;
    const int positions = file.add_positions({{0, 0, 0}, {7, 7, 7}, {7, 7, 7}});
    const std::vector<std::uint16_t> which = {1, 2};
    const std::vector<float> values = {1, 0, 0, 0, 1, 0};
    const int which_view = file.add_view(which.data(), which.size() * 2);
    const int values_view = file.add_view(values.data(), values.size() * 4);
    file.json["accessors"][positions]["sparse"] = {
        {"count", 2},
        {"indices", {{"bufferView", which_view}, {"componentType", testing::kUnsignedShort}}},
        {"values", {{"bufferView", values_view}}}};
    file.add_node({{"mesh", file.add_mesh({{"POSITION", positions}})}});
    file.write_gltf(dir / "sparse.gltf");
    const Scene scene = load_ok(dir / "sparse.gltf");
    EXPECT_TRUE(has_triangle(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
}

// Interleaved attributes through one strided view: position then normal, 24 bytes apart.
TEST(GltfGeometry, StridedInterleavedAttributes) {
    const auto dir = testing::test_directory("strided");
    TestGltf file;
    const std::vector<float> interleaved = {0, 0, 0,  0, 0, -1, 1, 0, 0,
                                            0, 0, -1, 0, 1, 0,  0, 0, -1};
    const int view = file.add_view(interleaved.data(), interleaved.size() * 4, 24);
    file.json["accessors"].push_back(
        {{"bufferView", view}, {"componentType", testing::kFloat}, {"count", 3}, {"type", "VEC3"}});
    file.json["accessors"].push_back({{"bufferView", view},
                                      {"byteOffset", 12},
                                      {"componentType", testing::kFloat},
                                      {"count", 3},
                                      {"type", "VEC3"}});
    file.add_node({{"mesh", file.add_mesh({{"POSITION", 0}, {"NORMAL", 1}})}});
    file.write_gltf(dir / "strided.gltf");
    const Scene scene = load_ok(dir / "strided.gltf");
    testing::expect_well_formed(scene);
    // The file's normals point to -z, against the winding: the normals decide (scene.h).
    EXPECT_TRUE(has_triangle(scene, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}));
    for (const Vertex& v : scene.vertices) EXPECT_TRUE(testing::near(v.normal, {0, 0, -1}));
}

// A 300 x 300 grid of quads (180 000 triangles, 1 m cells) chunks into compact chunks of at
// most the target: each chunk's footprint is a small part of the 300 m square.
TEST(GltfGeometry, LargeMeshChunksIntoCompactPieces) {
    const auto dir = testing::test_directory("grid");
    constexpr std::uint32_t kSide = 300;
    TestGltf file;
    std::vector<glm::vec3> v;
    for (std::uint32_t z = 0; z <= kSide; ++z) {
        for (std::uint32_t x = 0; x <= kSide; ++x)
            v.emplace_back(static_cast<float>(x), 0.0f, -static_cast<float>(z));
    }
    std::vector<std::uint32_t> indices;
    for (std::uint32_t z = 0; z < kSide; ++z) {
        for (std::uint32_t x = 0; x < kSide; ++x) {
            const std::uint32_t a = z * (kSide + 1) + x;
            const std::uint32_t b = a + 1;
            const std::uint32_t c = a + kSide + 1;
            const std::uint32_t d = c + 1;
            // (a, b, d) with a at (x, -z), b at (x+1, -z), d at (x+1, -z-1): counter-clockwise
            // seen from +y.
            indices.insert(indices.end(), {a, b, d, a, d, c});
        }
    }
    file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_positions(v)}},
                                          file.add_indices(indices))}});
    file.write_glb(dir / "grid.glb");
    GltfLoadOptions options = quiet();
    options.chunk_triangles = 2048;
    const Scene scene = load_ok(dir / "grid.glb", options);
    testing::expect_well_formed(scene, 2048);
    EXPECT_EQ(scene.triangle_count(), 2u * kSide * kSide);
    EXPECT_GE(scene.chunks.size(), 2u * kSide * kSide / 2048);
    double area = 0.0;
    for (const Chunk& chunk : scene.chunks) {
        EXPECT_GE(chunk.index_count / 3, 2048u / 2);  // median splits of cells over the target
        const glm::vec3 extent = chunk.bounds.max - chunk.bounds.min;
        EXPECT_LT(std::max(extent.x, extent.z), 0.25f * kSide);
        area += static_cast<double>(extent.x) * extent.z;
    }
    // Compact chunks barely overlap: their boxes cover little more than the grid itself.
    EXPECT_LT(area, 1.5 * kSide * kSide);
    for (const Vertex& vertex : scene.vertices) EXPECT_GT(vertex.normal.y, 0.99f);
}

}  // namespace
}  // namespace monoplane::scenes
