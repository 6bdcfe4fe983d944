// Malformed, unsupported and hostile glTF files written by the tests: each must give one error
// that names the file and the problem, never a crash, a hang or a half-read scene.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "scenes/gltf/load_gltf.h"
#include "tests/unit/gltf_test_files.h"

namespace monoplane::scenes {
namespace {

using nlohmann::json;
using testing::quiet;
using testing::TestGltf;

// The error message, which must start with the file's path.
std::string load_error(const std::filesystem::path& file,
                       const GltfLoadOptions& options = quiet()) {
    Result<Scene> scene = load_gltf_scene(file, options);
    EXPECT_FALSE(scene.ok()) << file << " loaded";
    if (scene.ok()) return {};
    const std::string& message = scene.error().message;
    EXPECT_EQ(message.rfind(file.string(), 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
}

// A valid one-triangle file to break in one place.
TestGltf triangle_file() {
    TestGltf file;
    const int positions = file.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    file.add_node({{"mesh", file.add_mesh({{"POSITION", positions}}, -1, 4, -1, "Tri")}});
    return file;
}

class GltfErrors : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = testing::test_directory(
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    }
    // Writes the file as .gltf with an embedded buffer and returns the error.
    std::string error_of(TestGltf& file, const GltfLoadOptions& options = quiet()) {
        file.write_gltf(dir_ / "bad.gltf");
        return load_error(dir_ / "bad.gltf", options);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    std::filesystem::path dir_;
};

TEST_F(GltfErrors, MissingFileAndEmptyFile) {
    EXPECT_EQ(load_error(dir_ / "nowhere.gltf"), path("nowhere.gltf") + ": not found");
    TestGltf::write_text(dir_ / "empty.glb", "");
    EXPECT_EQ(load_error(dir_ / "empty.glb"), path("empty.glb") + " is empty");
    std::filesystem::create_directory(dir_ / "folder.gltf");
    EXPECT_EQ(load_error(dir_ / "folder.gltf"),
              path("folder.gltf") + " is a directory, not a file");
}

TEST_F(GltfErrors, JsonSyntaxAndNesting) {
    TestGltf::write_text(dir_ / "syntax.gltf", "{\"asset\": {\"version\": \"2.0\"},, }");
    EXPECT_NE(load_error(dir_ / "syntax.gltf")
                  .find("syntax.gltf is not valid JSON: parse error at line 1"),
              std::string::npos);
    // extras nested 10 000 deep: tinygltf would recurse through all of them.
    std::string deep = "{\"asset\": {\"version\": \"2.0\"}, \"extras\": ";
    for (int i = 0; i < 10000; ++i) deep += "[";
    for (int i = 0; i < 10000; ++i) deep += "]";
    deep += "}";
    TestGltf::write_text(dir_ / "deep.gltf", deep);
    EXPECT_EQ(load_error(dir_ / "deep.gltf"),
              path("deep.gltf") + ": the JSON nests deeper than 64 levels");
}

TEST_F(GltfErrors, UnsupportedVersionsAndRequiredExtensions) {
    TestGltf file = triangle_file();
    file.json["asset"]["version"] = "1.0";
    EXPECT_EQ(error_of(file),
              path("bad.gltf") +
                  ": glTF 1.0 is not supported (asset.version is \"1.0\"): only glTF "
                  "2.0 is, convert the file to glTF 2.0");
    file.json["asset"]["version"] = "2.0";
    file.json["asset"]["minVersion"] = "2.1";
    EXPECT_EQ(error_of(file),
              path("bad.gltf") +
                  ": the file needs glTF 2.1 (asset.minVersion), this loader reads glTF 2.0");
    file.json["asset"].erase("minVersion");
    file.json["extensionsRequired"] = {"KHR_materials_unlit", "KHR_draco_mesh_compression"};
    file.json["extensionsUsed"] = file.json["extensionsRequired"];
    EXPECT_EQ(error_of(file),
              path("bad.gltf") +
                  ": the file requires the extension KHR_draco_mesh_compression "
                  "(compressed geometry this build cannot decode), which this loader "
                  "does not support");
    file.json["extensionsRequired"] = {"KHR_materials_unlit"};  // ignorable: loads
    file.write_gltf(dir_ / "unlit.gltf");
    EXPECT_TRUE(load_gltf_scene(dir_ / "unlit.gltf", quiet()).ok());
}

TEST_F(GltfErrors, SchemaTypesAndIndexRanges) {
    struct Case {
        std::string pointer;
        json value;
        std::string message;
    };
    const std::vector<Case> cases = {
        {"/scene", "hello", "scene must be a non-negative integer, not a string"},
        {"/meshes/0/primitives", json::object(),
         "meshes[0].primitives must be an array, not an object"},
        {"/nodes/0/mesh", 4, "nodes[0].mesh is 4, but the file has 1 mesh"},
        {"/nodes/0/translation", {1, 2}, "nodes[0].translation must have 3 elements, not 2"},
        {"/nodes/0/children", {-1}, "nodes[0].children[0] must be a non-negative integer, not -1"},
        {"/accessors/0/count", 0, "accessors[0].count must be at least 1, not 0"},
        {"/accessors/0/bufferView", 1.5,
         "accessors[0].bufferView must be a non-negative integer, not a number"},
        {"/meshes/0/primitives/0/attributes/POSITION", 3,
         "meshes[0].primitives[0].attributes.POSITION is 3, but the file has 1 accessor"},
        {"/nodes/0/extensions",
         {{"EXT_x", 1}},
         "nodes[0].extensions.EXT_x must be an object, not an integer"},
        {"/materials",
         {{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1}}}}}},
         "materials[0].pbrMetallicRoughness.baseColorFactor must have 4 elements, not 3"},
        {"/buffers", json::object(), "buffers must be an array, not an object"},
    };
    for (const Case& c : cases) {
        TestGltf file = triangle_file();
        file.write_gltf(dir_ / "bad.gltf");
        json document = json::parse(std::ifstream(dir_ / "bad.gltf"));
        document[json::json_pointer(c.pointer)] = c.value;
        TestGltf::write_text(dir_ / "bad.gltf", document.dump());
        EXPECT_EQ(load_error(dir_ / "bad.gltf"), path("bad.gltf") + ": " + c.message) << c.pointer;
    }
}

TEST_F(GltfErrors, BufferSources) {
    TestGltf file = triangle_file();
    file.json["buffers"] = {{{"byteLength", 36}, {"uri", "missing.bin"}}};
    TestGltf::write_text(dir_ / "missing.gltf", file.json.dump());
    EXPECT_EQ(
        load_error(dir_ / "missing.gltf"),
        path("missing.gltf") + ": buffer 0: file \"missing.bin\" not found in " + dir_.string());

    file.write_gltf_with_bin(dir_ / "short.gltf", "short.bin");
    TestGltf::write_text(dir_ / "short.bin", std::string(20, '\0'));
    EXPECT_EQ(load_error(dir_ / "short.gltf"),
              path("short.gltf") +
                  ": buffer 0: file \"short.bin\" has 20 bytes, but the buffer's byteLength is 36");

    file.json["buffers"] = {{{"byteLength", 36}, {"uri", "http://example.com/box.bin"}}};
    TestGltf::write_text(dir_ / "remote.gltf", file.json.dump());
    EXPECT_EQ(load_error(dir_ / "remote.gltf"),
              path("remote.gltf") +
                  ": buffer 0's uri \"http://example.com/box.bin\" is not a path "
                  "relative to the glTF file (other URIs are not supported)");

    file.json["buffers"] = {
        {{"byteLength", 36}, {"uri", "data:application/octet-stream;base64,AAAA"}}};
    TestGltf::write_text(dir_ / "data.gltf", file.json.dump());
    EXPECT_EQ(load_error(dir_ / "data.gltf"),
              path("data.gltf") + ": buffer 0's data: URI holds 3 bytes, but its byteLength is 36");

    file.json["buffers"] = {{{"byteLength", 36}}};
    TestGltf::write_text(dir_ / "nouri.gltf", file.json.dump());
    EXPECT_EQ(
        load_error(dir_ / "nouri.gltf"),
        path("nouri.gltf") + ": buffer 0 has no uri (only a .glb's first buffer may omit it)");
}

TEST_F(GltfErrors, GlbContainer) {
    TestGltf file = triangle_file();
    file.write_glb(dir_ / "good.glb");
    std::ifstream in(dir_ / "good.glb", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_TRUE(load_gltf_scene(dir_ / "good.glb", quiet()).ok());

    TestGltf::write_text(dir_ / "truncated.glb", bytes.substr(0, bytes.size() - 8));
    EXPECT_EQ(load_error(dir_ / "truncated.glb"),
              path("truncated.glb") + " is truncated: its header says " +
                  std::to_string(bytes.size()) + " bytes, the file has " +
                  std::to_string(bytes.size() - 8));
    std::string v1 = bytes;
    v1[4] = 1;
    TestGltf::write_text(dir_ / "v1.glb", v1);
    EXPECT_EQ(load_error(dir_ / "v1.glb"), path("v1.glb") +
                                               " is binary glTF version 1 (glTF 1.0), which is not "
                                               "supported: convert the file to glTF 2.0");
    TestGltf::write_text(dir_ / "short.glb", bytes.substr(0, 14));
    EXPECT_EQ(
        load_error(dir_ / "short.glb"),
        path("short.glb") + " is too short (14 bytes) for a binary glTF header and JSON chunk");
    // Every truncation of a valid file fails cleanly (or, cut after the BIN chunk, loads).
    for (std::size_t size = 0; size < bytes.size(); size += 3) {
        TestGltf::write_text(dir_ / "cut.glb", bytes.substr(0, size));
        EXPECT_FALSE(load_gltf_scene(dir_ / "cut.glb", quiet()).ok()) << size;
    }
}

TEST_F(GltfErrors, AccessorsReadingPastTheirData) {
    {
        TestGltf file = triangle_file();
        file.json["accessors"][0]["count"] = 4;
        EXPECT_EQ(error_of(file),
                  path("bad.gltf") +
                      ": accessor 0 (POSITION of mesh 'Tri' primitive 0): count 4 "
                      "with stride 12 from byte 0 reads past the end of buffer view 0 "
                      "(36 bytes)");
    }
    {
        TestGltf file = triangle_file();
        file.json["accessors"][0]["byteOffset"] = 4;
        EXPECT_NE(error_of(file).find("count 3 with stride 12 from byte 4 reads past the end"),
                  std::string::npos);
    }
    {
        TestGltf file = triangle_file();
        file.json["bufferViews"][0]["byteStride"] = 8;
        EXPECT_EQ(error_of(file),
                  path("bad.gltf") +
                      ": accessor 0 (POSITION of mesh 'Tri' primitive 0): byteStride 8 "
                      "of buffer view 0 is smaller than one element (12 bytes)");
    }
    {
        // A view past its buffer: tinygltf checks nothing, the reader does.
        TestGltf file = triangle_file();
        file.bin.resize(48, 0);
        file.json["bufferViews"][0]["byteOffset"] = 24;
        EXPECT_EQ(error_of(file),
                  path("bad.gltf") +
                      ": accessor 0 (POSITION of mesh 'Tri' primitive 0): buffer view 0 "
                      "(bytes 24 to 60) lies outside buffer 0 (48 bytes)");
    }
    {
        // A claimed count far beyond anything, without a buffer view (zeros): refused before any
        // allocation.
        TestGltf file = triangle_file();
        file.json["accessors"].push_back(
            {{"componentType", testing::kFloat}, {"count", 4000000000u}, {"type", "VEC3"}});
        file.json["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 1;
        EXPECT_EQ(error_of(file),
                  path("bad.gltf") +
                      ": the scene has 1333333333 triangles once every mesh instance "
                      "is counted, more than the limit of 67108864 "
                      "(GltfLoadOptions::max_triangles)");
    }
}

TEST_F(GltfErrors, WrongAccessorTypes) {
    struct Case {
        std::function<void(TestGltf&)> change;
        std::string message;
    };
    const std::vector<Case> cases = {
        {[](TestGltf& f) {
             f.json["accessors"][0]["type"] = "VEC2";
             f.json["accessors"][0]["count"] = 4;
         },
         "accessor 0 (POSITION of mesh 'Tri' primitive 0): is VEC2, but must be VEC3"},
        {[](TestGltf& f) { f.json["accessors"][0]["componentType"] = testing::kUnsignedShort; },
         "accessor 0 (POSITION of mesh 'Tri' primitive 0): has component type UNSIGNED_SHORT, but "
         "must be FLOAT"},
        {[](TestGltf& f) { f.json["accessors"][0]["normalized"] = true; },
         "accessor 0 (POSITION of mesh 'Tri' primitive 0): is FLOAT and normalized, which glTF "
         "forbids"},
        {[](TestGltf& f) {
             f.json["meshes"][0]["primitives"][0]["indices"] =
                 f.add_accessor(std::vector<float>{0, 1, 2}, testing::kFloat, "SCALAR", 3);
         },
         "accessor 1 (indices of mesh 'Tri' primitive 0): has component type FLOAT, but indices "
         "must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT"},
        {[](TestGltf& f) {
             f.json["meshes"][0]["primitives"][0]["indices"] =
                 f.add_indices({0, 1, 3}, testing::kUnsignedShort);
         },
         "accessor 1 (indices of mesh 'Tri' primitive 0): index 3 at position 2 is out of range "
         "(the "
         "primitive has 3 vertices)"},
        {[](TestGltf& f) {
             f.json["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] =
                 f.add_positions({{0, 0, 1}, {0, 0, 1}});
         },
         "NORMAL of mesh 'Tri' primitive 0 has 2 elements, but POSITION has 3"},
        {[](TestGltf& f) {
             f.json["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] =
                 f.add_accessor(std::vector<std::uint8_t>{255, 0, 0, 255, 0, 0, 255, 0, 0},
                                testing::kUnsignedByte, "VEC3", 3);
         },
         "accessor 1 (COLOR_0 of mesh 'Tri' primitive 0): is UNSIGNED_BYTE but not normalized"},
        {[](TestGltf& f) { f.json["meshes"][0]["primitives"][0]["mode"] = 9; },
         "mesh 'Tri' primitive 0: mode 9 is not a glTF primitive mode"},
        {[](TestGltf& f) { f.json["accessors"][0]["type"] = "VEC7"; },
         "cannot be read by tinygltf: Unsupported `type` for accessor object. Got \"VEC7\""},
    };
    for (const Case& c : cases) {
        TestGltf file = triangle_file();
        c.change(file);
        EXPECT_EQ(error_of(file), path("bad.gltf") + ": " + c.message);
    }
}

TEST_F(GltfErrors, NonFinitePositions) {
    TestGltf file;
    const float inf = std::numeric_limits<float>::infinity();
    const int positions = file.add_positions({{0, 0, 0}, {inf, 0, 0}, {0, 1, 0}});
    file.add_node({{"mesh", file.add_mesh({{"POSITION", positions}})}});
    EXPECT_EQ(error_of(file),
              path("bad.gltf") +
                  ": accessor 0 (POSITION of mesh 0 primitive 0): element 1 is not finite (inf)");
    TestGltf far = triangle_file();
    far.json["nodes"][0]["scale"] = {1e30, 1, 1};
    EXPECT_NE(error_of(far).find(
                  "POSITION of mesh 'Tri' primitive 0: vertex 1 lands at (1e+30, 0, 0) in the "
                  "world, beyond 1e+07 m from the origin"),
              std::string::npos);
}

TEST_F(GltfErrors, SparseIndicesOutOfRange) {
    TestGltf file = triangle_file();
    const std::vector<std::uint16_t> which = {5};
    const std::vector<float> values = {1, 1, 1};
    const int which_view = file.add_view(which.data(), 2);
    const int values_view = file.add_view(values.data(), 12);
    file.json["accessors"][0]["sparse"] = {
        {"count", 1},
        {"indices", {{"bufferView", which_view}, {"componentType", testing::kUnsignedShort}}},
        {"values", {{"bufferView", values_view}}}};
    EXPECT_EQ(error_of(file),
              path("bad.gltf") +
                  ": accessor 0 (POSITION of mesh 'Tri' primitive 0): sparse index 5 "
                  "(entry 0) is out of range or not above the one before it");
}

TEST_F(GltfErrors, NodeHierarchy) {
    {
        TestGltf file = triangle_file();
        file.json["nodes"][0]["children"] = {1};
        file.add_node({{"children", {0}}}, false);
        EXPECT_EQ(error_of(file),
                  path("bad.gltf") +
                      ": the node hierarchy has a cycle (0 -> 1 -> 0): node 0 is its "
                      "own ancestor, but glTF nodes form trees");
    }
    {
        TestGltf file = triangle_file();
        file.json["nodes"][0]["children"] = {0};
        EXPECT_EQ(error_of(file), path("bad.gltf") + ": node 0 is its own child");
    }
    {
        // Two parents: a diamond would draw the shared node twice (and chains of diamonds
        // 2^n times).
        TestGltf file = triangle_file();
        file.add_node({{"children", {0}}}, true);
        file.add_node({{"children", {0}}}, true);
        file.json["scenes"][0]["nodes"] = {1, 2};
        EXPECT_EQ(
            error_of(file),
            path("bad.gltf") + ": node 0 has two parents (nodes 1 and 2): glTF nodes form trees");
    }
    {
        // A chain of 100 000 nodes: deep, but no stack overflow.
        TestGltf file = triangle_file();
        file.json["scenes"][0]["nodes"] = {1};
        for (int i = 1; i <= 100000; ++i) {
            file.json["nodes"].push_back({{"children", {i == 100000 ? 0 : i + 1}}});
        }
        file.write_gltf(dir_ / "chain.gltf");
        Result<Scene> scene = load_gltf_scene(dir_ / "chain.gltf", quiet());
        // The JSON is only 4 levels deep; the hierarchy is what is deep.
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        EXPECT_EQ(scene->triangle_count(), 1u);
    }
    {
        TestGltf file = triangle_file();
        file.json["nodes"][0]["rotation"] = {0, 0, 0, 0};
        EXPECT_EQ(error_of(file), path("bad.gltf") + ": node 0: rotation is not a unit quaternion");
    }
}

TEST_F(GltfErrors, NothingToDraw) {
    {
        TestGltf file = triangle_file();
        file.json["meshes"][0]["primitives"][0]["mode"] = 1;  // lines
        EXPECT_EQ(
            error_of(file),
            path("bad.gltf") + " has no triangles to draw (only 1 primitive of points or lines)");
    }
    {
        TestGltf file = triangle_file();
        file.json["scenes"][0]["nodes"] = json::array();
        EXPECT_EQ(error_of(file),
                  path("bad.gltf") + " has no triangles to draw (its scene has no meshes)");
    }
    {
        TestGltf file;
        const int positions = file.add_positions({{0, 0, 0}, {1, 0, 0}});
        file.add_node(
            {{"mesh", file.add_mesh({{"POSITION", positions}}, file.add_indices({0, 1, 1}))}});
        EXPECT_EQ(error_of(file),
                  path("bad.gltf") + " has no triangles to draw (only 1 degenerate triangle)");
    }
}

// One mesh instanced by many nodes: the expanded scene exceeds the limit before anything is
// built.
TEST_F(GltfErrors, InstancingBeyondTheTriangleLimit) {
    TestGltf file = triangle_file();
    for (int i = 0; i < 9; ++i) file.add_node({{"mesh", 0}});
    GltfLoadOptions options = quiet();
    options.max_triangles = 5;
    EXPECT_EQ(error_of(file, options),
              path("bad.gltf") +
                  ": the scene has 10 triangles once every mesh instance is "
                  "counted, more than the limit of 5 "
                  "(GltfLoadOptions::max_triangles)");
}

}  // namespace
}  // namespace monoplane::scenes
