// glTF 2.0 import (docs/scenes.md, "Imported scenes"): a .gltf (external or data: buffers
// and images) or .glb file becomes a scenes::Scene, chunked for culling like the procedural
// scenes, with a default viewpoint. CPU only, no Vulkan.
//
// Malformed, unsupported or absurdly large files give one error naming the file and the problem,
// never a crash and never a half-read scene: every count, offset, stride and index the file
// states is checked against the bytes it really has before it is read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "common/result.h"
#include "scenes/scene.h"

namespace monoplane::scenes {

// glTF leaves normals to the client where a primitive has none.
enum class GeneratedNormals {
    // Area-weighted average of the faces around each vertex: smooth surfaces (scans, CAD
    // tessellations) stay smooth, and shared vertices stay shared.
    Smooth,
    // One normal per face, what the glTF 2.0 specification asks for; every triangle gets its own
    // three vertices.
    Flat,
};

struct GltfLoadOptions {
    // Chunks get at most this many triangles, and at least half as many where there are more
    // (clamped to [64, kMaxChunkTriangles]).
    std::uint32_t chunk_triangles = 2048;
    GeneratedNormals generated_normals = GeneratedNormals::Smooth;
    // Refuse scenes that would expand (every mesh instance counted) to more triangles than this:
    // a small file can instance a big mesh many times over. 64 M triangles take a few GB; more
    // than 2^29 are never allowed (32-bit indices).
    std::uint64_t max_triangles = 64u << 20;
    // Refuse scenes whose base-colour images hold more texels than this in all (a small PNG can
    // claim a huge size); 64 M texels take 256 MB.
    std::uint64_t max_texture_texels = 8192u * 8192u;
    // A progress line on stderr about once a second while a load takes longer than a second.
    bool progress = true;
    // One line on stderr saying what was skipped or ignored (points and lines, extensions,
    // skins...); the same lines are in GltfLoadReport::warnings.
    bool print_warnings = true;
};

// What a load skipped or worked around: each is also a reason the scene looks different from what
// a full glTF viewer would show.
struct GltfLoadReport {
    std::size_t primitives_skipped_points_or_lines = 0;
    std::size_t primitives_skipped_without_positions = 0;
    std::size_t indices_dropped_incomplete = 0;    // a list's or strip's tail of fewer than 3
    std::size_t triangles_dropped_degenerate = 0;  // two equal indices (strip restarts, mostly)
    std::size_t normals_generated = 0;             // vertices whose normal the loader computed
    std::size_t textures_without_texcoords = 0;    // primitives drawn without their texture
    std::vector<std::string> warnings;             // one line each, without the file name
    // Every file the load read: the .gltf/.glb first, then its external buffers and images in
    // the order read, each once (lexically normal paths as the loader opened them). What a
    // study session records the digests of (docs/scenes.md).
    std::vector<std::filesystem::path> files_read;
    double seconds = 0.0;
};

// Reads a glTF 2.0 scene: the file's default scene (or its first, or, without any, every root
// node), meshes in TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN mode, node transforms, base-colour
// factor, vertex colour and texture, roughness, alpha mode and cut-off (Chunk::alpha_mode). The
// scene's id is SceneId::Imported and its name the file's stem. Any thread, any time; report
// (optional) says what was skipped.
Result<Scene> load_gltf_scene(const std::filesystem::path& file,
                              const GltfLoadOptions& options = {},
                              GltfLoadReport* report = nullptr);

}  // namespace monoplane::scenes
