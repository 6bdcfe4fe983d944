// Fuzz target: glTF import (scenes/gltf/load_gltf.h). Seeds are small .gltf files; the .bin and
// .png they name are copied beside the input, so mutated counts, offsets, strides and indices
// are read against real buffers. Whatever the loader accepts must be a scene the renderer can
// draw: the structural promises of scenes/scene.h, checked below.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <glm/geometric.hpp>

#include "scenes/chunk_builder.h"
#include "scenes/gltf/load_gltf.h"
#include "tests/fuzz/fuzz_runner.h"
#include "tests/fuzz/mutator.h"

namespace monoplane {
namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string broken_promise(const scenes::Scene& s) {
    if (s.chunks.empty() || s.indices.empty()) return "no chunks";
    if (s.viewpoints.empty() || s.viewpoints.front().name != "default")
        return "no default viewpoint";
    for (const scenes::Viewpoint& v : s.viewpoints) {
        if (!std::isfinite(v.head.position.x + v.head.position.y + v.head.position.z) ||
            !(std::abs(glm::length(v.head.orientation) - 1.0) < 1e-6))
            return "a viewpoint that is not a pose";
    }
    if (!s.textures.empty() && s.texcoords.size() != s.vertices.size())
        return "texcoords not parallel";
    std::uint64_t next = 0;
    for (const scenes::Chunk& chunk : s.chunks) {
        if (chunk.first_index != next || chunk.index_count == 0 || chunk.index_count % 3 != 0)
            return "chunks that do not tile the index buffer";
        next += chunk.index_count;
        if (chunk.index_count / 3 > scenes::kMaxChunkTriangles) return "an oversized chunk";
        if (chunk.vertex_offset < 0) return "a negative vertex offset";
        if (chunk.texture >= static_cast<std::int32_t>(s.textures.size()) || chunk.texture < -1)
            return "a chunk texture out of range";
        for (std::uint32_t i = chunk.first_index; i < chunk.first_index + chunk.index_count;
             i += 3) {
            const scenes::Vertex* corner[3];
            for (std::uint32_t k = 0; k < 3; ++k) {
                const std::uint64_t v = std::uint64_t{s.indices[i + k]} +
                                        static_cast<std::uint64_t>(chunk.vertex_offset);
                if (v >= s.vertices.size()) return "an index out of range";
                corner[k] = &s.vertices[v];
                const glm::vec3& p = corner[k]->position;
                if (!finite(p) || !finite(corner[k]->normal) ||
                    !(std::abs(glm::length(corner[k]->normal) - 1.0f) < 1e-3f))
                    return "a vertex that is not finite or not unit-normal";
                if (glm::any(glm::lessThan(p, chunk.bounds.min)) ||
                    glm::any(glm::greaterThan(p, chunk.bounds.max)))
                    return "a vertex outside its chunk's bounds";
            }
            const glm::vec3 face = glm::cross(corner[1]->position - corner[0]->position,
                                              corner[2]->position - corner[0]->position);
            if (glm::dot(face, corner[0]->normal + corner[1]->normal + corner[2]->normal) < 0.0f)
                return "a triangle winding against its normals";
        }
    }
    if (next != s.indices.size()) return "indices beyond the last chunk";
    return {};
}

TEST(Fuzz, GltfScene) {
    const std::filesystem::path work = fuzz::work_folder("gltf_scene");
    for (const char* resource : {"hierarchy.bin", "tex.png"}) {
        std::filesystem::copy_file(fuzz::corpus_path("gltf_scene") / "resources" / resource,
                                   work / resource,
                                   std::filesystem::copy_options::overwrite_existing);
    }
    const fuzz::FuzzTarget target{
        .name = "gltf_scene",
        .seeds = {fuzz::corpus_path("gltf_scene")},
        .dictionary = fuzz::split_words(R"(
asset version "2.0" "1.0" minVersion extensionsRequired extensionsUsed "KHR_draco_mesh_compression"
scene scenes nodes children mesh camera matrix translation rotation scale meshes primitives
attributes "POSITION" "NORMAL" "TEXCOORD_0" "TEXCOORD_1" "COLOR_0" indices mode material
accessors bufferView byteOffset componentType count type normalized sparse values
"SCALAR" "VEC2" "VEC3" "VEC4" "MAT4" bufferViews buffer byteLength byteStride buffers uri
"hierarchy.bin" "tex.png" materials pbrMetallicRoughness baseColorFactor baseColorTexture index
texCoord roughnessFactor metallicFactor textures source sampler samplers wrapS wrapT images
cameras perspective yfov znear extras extensions 5120 5121 5122 5123 5125 5126 33071 33648
10497 4294967295 65535 255 -1 0 1 2 3 4 5 6 7
)"),
        .file_extension = ".gltf",
        .iterations = 6000,
        .run = [](const fuzz::FuzzInput& input) {
            scenes::GltfLoadOptions options;
            options.progress = false;
            options.print_warnings = false;
            // Small limits keep each mutant fast; the limits themselves are what is tested.
            options.max_triangles = 1u << 16;
            options.max_texture_texels = 1u << 16;
            const Result<scenes::Scene> scene = scenes::load_gltf_scene(input.file, options);
            if (!scene) return fuzz::rejected(scene.error(), input);
            if (std::string broken = broken_promise(*scene); !broken.empty())
                return fuzz::violation("accepted a scene with " + broken);
            if (scene->triangle_count() > options.max_triangles)
                return fuzz::violation("more triangles than max_triangles");
            return fuzz::accepted();
        }};
    fuzz::expect_clean(fuzz::run_fuzz_target(target));
}

}  // namespace
}  // namespace monoplane
