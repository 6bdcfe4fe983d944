#include "scenes/gltf/load_gltf.h"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <limits>
#include <optional>
#include <utility>

#include "scenes/gltf/chunk_assembly.h"
#include "scenes/gltf/gltf_document.h"
#include "scenes/gltf/imported_geometry.h"
#include "scenes/gltf/imported_viewpoints.h"
#include "scenes/gltf/load_progress.h"
#include "scenes/gltf/node_instances.h"
#include "scenes/gltf/primitive_import.h"
#include "scenes/gltf/primitive_topology.h"
#include "scenes/gltf/surface_look.h"
#include "scenes/gltf/texture_set.h"

namespace monoplane::scenes {
namespace {

using namespace gltf;

// Whatever the options say: Scene::indices and vertex offsets are 32-bit, and a scene has at
// most three vertices per triangle of its own.
constexpr std::uint64_t kHardTriangleLimit = 1u << 29;

std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b) {
    return a > std::numeric_limits<std::uint64_t>::max() - b
               ? std::numeric_limits<std::uint64_t>::max()
               : a + b;
}

// Refuses, before anything is expanded, a scene whose mesh instances together would exceed the
// triangle limit (a small file can instance a big mesh many times), counting what the accessors
// claim; the readers check the claims later.
Result<void> check_expanded_size(const tinygltf::Model& model,
                                 const std::vector<NodeInstance>& meshes,
                                 const GltfLoadOptions& options, std::uint64_t max_triangles) {
    std::uint64_t triangles = 0;
    std::uint64_t vertices = 0;
    const auto count_of = [&](int accessor) -> std::uint64_t {
        return accessor >= 0 && static_cast<std::size_t>(accessor) < model.accessors.size()
                   ? model.accessors[static_cast<std::size_t>(accessor)].count
                   : 0;
    };
    for (const NodeInstance& instance : meshes) {
        if (instance.index < 0 || static_cast<std::size_t>(instance.index) >= model.meshes.size()) {
            return Error{"node " + std::to_string(instance.node) + " names mesh " +
                         std::to_string(instance.index) + ", which does not exist"};
        }
        for (const tinygltf::Primitive& primitive :
             model.meshes[static_cast<std::size_t>(instance.index)].primitives) {
            const int mode =
                primitive.mode < 0 ? static_cast<int>(PrimitiveMode::Triangles) : primitive.mode;
            const auto position = primitive.attributes.find("POSITION");
            if (!is_triangle_mode(mode) || position == primitive.attributes.end()) continue;
            const std::uint64_t positions = count_of(position->second);
            const std::uint64_t sequence =
                primitive.indices >= 0 ? count_of(primitive.indices) : positions;
            const std::uint64_t added = mode == static_cast<int>(PrimitiveMode::Triangles)
                                            ? sequence / 3
                                            : (sequence >= 3 ? sequence - 2 : 0);
            const bool flat = options.generated_normals == GeneratedNormals::Flat &&
                              primitive.attributes.count("NORMAL") == 0;
            const std::uint64_t corners = saturating_add(saturating_add(added, added), added);
            // A double-sided primitive's back faces are triangles and vertices of their own.
            const int sides = is_double_sided(model, primitive.material) ? 2 : 1;
            for (int side = 0; side < sides; ++side) {
                triangles = saturating_add(triangles, added);
                vertices = saturating_add(vertices, flat ? corners : positions);
            }
        }
    }
    if (triangles > max_triangles) {
        return Error{"the scene has " + std::to_string(triangles) +
                     " triangles once every mesh instance is counted, more than the limit of " +
                     std::to_string(max_triangles) + " (GltfLoadOptions::max_triangles)"};
    }
    if (vertices > 3 * max_triangles) {
        return Error{"the scene has " + std::to_string(vertices) +
                     " vertices once every mesh instance is counted, more than three per allowed "
                     "triangle (" +
                     std::to_string(3 * max_triangles) + ")"};
    }
    return Ok{};
}

// "1 primitive", "2 primitives"; "1 index", "2 indices".
std::string plural(std::size_t count, const std::string& noun) {
    const std::string many = noun == "index" ? "indices" : noun + "s";
    return std::to_string(count) + " " + (count == 1 ? noun : many);
}

// One line of what the scene lacks compared with a full glTF viewer.
std::vector<std::string> warnings_for(const tinygltf::Model& model, const GltfLoadReport& report) {
    std::vector<std::string> lines;
    if (report.primitives_skipped_points_or_lines > 0) {
        lines.push_back("skipped " +
                        plural(report.primitives_skipped_points_or_lines, "primitive") +
                        " of points or lines");
    }
    if (report.primitives_skipped_without_positions > 0) {
        lines.push_back("skipped " +
                        plural(report.primitives_skipped_without_positions, "primitive") +
                        " without POSITION");
    }
    if (report.indices_dropped_incomplete > 0) {
        lines.push_back("dropped " + plural(report.indices_dropped_incomplete, "index") +
                        " that complete no triangle");
    }
    if (report.textures_without_texcoords > 0) {
        lines.push_back("drew " + plural(report.textures_without_texcoords, "primitive") +
                        " without its base-colour texture (no TEXCOORD_n for it)");
    }
    // The loader implements no extension: those a file requires were checked (gltf_support.h),
    // those it merely uses are left out.
    std::string ignored;
    for (const std::string& extension : model.extensionsUsed) {
        ignored += (ignored.empty() ? "" : ", ") + extension;
    }
    if (!ignored.empty()) lines.push_back("ignores extensions " + ignored);
    if (!model.skins.empty() || !model.animations.empty()) {
        lines.push_back("ignores skins and animations (meshes are drawn in their rest pose)");
    }
    return lines;
}

Error nothing_to_draw(const GltfLoadReport& report, std::size_t mesh_instances) {
    std::string why = "has no triangles to draw";
    if (mesh_instances == 0) return Error{why + " (its scene has no meshes)"};
    std::vector<std::string> reasons;
    if (report.primitives_skipped_points_or_lines > 0) {
        reasons.push_back(plural(report.primitives_skipped_points_or_lines, "primitive") +
                          " of points or lines");
    }
    if (report.primitives_skipped_without_positions > 0) {
        reasons.push_back(plural(report.primitives_skipped_without_positions, "primitive") +
                          " without POSITION");
    }
    if (report.triangles_dropped_degenerate > 0) {
        reasons.push_back(plural(report.triangles_dropped_degenerate, "degenerate triangle"));
    }
    if (!reasons.empty()) {
        why += " (only ";
        for (std::size_t i = 0; i < reasons.size(); ++i) why += (i == 0 ? "" : ", ") + reasons[i];
        why += ")";
    }
    return Error{why};
}

Result<Scene> load(const std::filesystem::path& file, const GltfLoadOptions& options,
                   GltfLoadReport& report) {
    LoadProgress progress(file.filename().string(), options.progress);
    Result<GltfDocument> read = read_gltf_document(file);
    MONOPLANE_TRY(read);
    GltfDocument& document = read.value();
    const tinygltf::Model& model = document.model;
    report.files_read = document.files_read;

    Result<SceneInstances> instances = instantiate_scene(model);
    MONOPLANE_TRY(instances);
    const std::uint64_t max_triangles = std::min(options.max_triangles, kHardTriangleLimit);
    MONOPLANE_TRY(check_expanded_size(model, instances->meshes, options, max_triangles));
    GltfLoadOptions bounded = options;
    bounded.max_triangles = max_triangles;

    ImportedGeometry geometry;
    TextureSet textures(document, options.max_texture_texels);
    const std::size_t total = instances->meshes.size();
    for (std::size_t i = 0; i < total; ++i) {
        const NodeInstance& instance = instances->meshes[i];
        const auto& primitives = model.meshes[static_cast<std::size_t>(instance.index)].primitives;
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            const PrimitiveSource source{model, instance.index, static_cast<int>(p),
                                         instance.world};
            MONOPLANE_TRY(import_primitive(source, bounded, textures, report, geometry));
        }
        progress.meshes(i + 1, total, geometry.triangle_count());
    }
    if (geometry.indices.empty()) return nothing_to_draw(report, total);
    report.warnings = warnings_for(model, report);
    std::optional<rig::Pose> camera;
    if (instances->camera) {
        camera = camera_pose(instances->camera->world);
        if (!camera) {
            report.warnings.push_back("camera node " + std::to_string(instances->camera->node) +
                                      " has a mirroring or singular transform: the default "
                                      "viewpoint frames the scene instead");
        }
    }
    document.model = tinygltf::Model{};  // the buffers are read: free them before chunking

    Scene scene;
    scene.id = SceneId::Imported;
    scene.name = file.stem().string();
    const std::size_t triangles = geometry.triangle_count();
    assemble_chunks(geometry, options.chunk_triangles, scene,
                    [&](std::size_t done) { progress.chunking(done, triangles); });
    geometry = ImportedGeometry{};
    scene.textures = textures.take();
    scene.viewpoints = imported_viewpoints(scene, camera);
    return scene;
}

}  // namespace

Result<Scene> load_gltf_scene(const std::filesystem::path& file, const GltfLoadOptions& options,
                              GltfLoadReport* report) {
    const auto start = std::chrono::steady_clock::now();
    GltfLoadReport local;
    GltfLoadReport& out = report != nullptr ? *report : local;
    out = GltfLoadReport{};
    Result<Scene> scene = load(file, options, out);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!scene) {
        // "big.glb is empty", "big.glb has no triangles to draw", "big.glb: buffer 0: ...".
        const std::string& problem = scene.error().message;
        const bool verb = problem.rfind("is ", 0) == 0 || problem.rfind("has ", 0) == 0;
        return Error{file.string() + (verb ? " " : ": ") + problem};
    }
    if (options.print_warnings && !out.warnings.empty()) {
        std::string line = file.string() + ": warning: ";
        for (std::size_t i = 0; i < out.warnings.size(); ++i)
            line += (i == 0 ? "" : "; ") + out.warnings[i];
        std::cerr << line << '\n';
    }
    return scene;
}

}  // namespace monoplane::scenes
