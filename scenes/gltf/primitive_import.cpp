#include "scenes/gltf/primitive_import.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <sstream>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat3x3.hpp>

#include "scenes/gltf/accessor_reader.h"
#include "scenes/gltf/primitive_topology.h"
#include "scenes/gltf/surface_look.h"
#include "scenes/gltf/vertex_normals.h"

namespace monoplane::scenes::gltf {
namespace {

constexpr std::array kVec2 = {TINYGLTF_TYPE_VEC2};
constexpr std::array kVec3 = {TINYGLTF_TYPE_VEC3};
constexpr std::array kColourTypes = {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4};

// No accessor may hold more elements than three per allowed triangle: this bounds every
// allocation by the triangle limit, whatever counts the file claims.
std::size_t element_limit(const GltfLoadOptions& options) {
    constexpr std::uint64_t kMost = std::numeric_limits<std::uint32_t>::max();
    return static_cast<std::size_t>(std::min<std::uint64_t>(kMost, 3 * options.max_triangles));
}

int attribute(const tinygltf::Primitive& primitive, const std::string& name) {
    const auto found = primitive.attributes.find(name);
    return found == primitive.attributes.end() ? -1 : found->second;
}

Error count_mismatch(const std::string& semantic, const std::string& where, std::size_t count,
                     std::size_t positions) {
    return Error{semantic + " of " + where + " has " + std::to_string(count) +
                 " elements, but POSITION has " + std::to_string(positions)};
}

// Positions through the world transform, refused beyond kMaxCoordinate.
Result<std::vector<glm::vec3>> to_world(const FloatElements& positions, const glm::dmat4& world,
                                        const std::string& where) {
    std::vector<glm::vec3> result(positions.count);
    for (std::size_t i = 0; i < positions.count; ++i) {
        const float* p = &positions.values[3 * i];
        const glm::dvec3 w(world * glm::dvec4(p[0], p[1], p[2], 1.0));
        if (!(std::fabs(w.x) <= kMaxCoordinate && std::fabs(w.y) <= kMaxCoordinate &&
              std::fabs(w.z) <= kMaxCoordinate)) {
            std::ostringstream text;
            text << "POSITION of " << where << ": vertex " << i << " lands at (" << w.x << ", "
                 << w.y << ", " << w.z << ") in the world, beyond " << kMaxCoordinate
                 << " m from the origin";
            return Error{text.str()};
        }
        result[i] = glm::vec3(w);
    }
    return result;
}

// glTF's doubleSided: the batch's triangles seen from behind, as triangles of their own with
// the winding reversed and the normals turned, so that they stay counter-clockwise about their
// normals (scene.h) and survive back-face culling exactly where the front faces do not.
void add_back_faces(GeometryBatch& batch, ImportedGeometry& geometry) {
    const std::size_t front_first_vertex = batch.first_vertex;
    const std::size_t front_vertices = batch.vertex_count;
    for (std::size_t k = 0; k < front_vertices; ++k) {
        Vertex back = geometry.vertices[front_first_vertex + k];
        back.normal = -back.normal;
        geometry.vertices.push_back(back);
        geometry.texcoords.push_back(geometry.texcoords[front_first_vertex + k]);
    }
    const std::size_t front_indices = batch.index_count;
    const auto offset = static_cast<std::uint32_t>(front_vertices);
    for (std::size_t t = 0; t < front_indices; t += 3) {
        const std::uint32_t* front = &geometry.indices[batch.first_index + t];
        const std::uint32_t a = front[0] + offset;
        const std::uint32_t b = front[1] + offset;
        const std::uint32_t c = front[2] + offset;
        geometry.indices.insert(geometry.indices.end(), {a, c, b});
    }
    batch.vertex_count = static_cast<std::uint32_t>(2 * front_vertices);
    batch.index_count = 2 * front_indices;
}

}  // namespace

std::string describe_primitive(const tinygltf::Model& model, int mesh, int primitive) {
    const std::string& name = model.meshes[static_cast<std::size_t>(mesh)].name;
    return (name.empty() ? "mesh " + std::to_string(mesh) : "mesh '" + name + "'") + " primitive " +
           std::to_string(primitive);
}

Result<bool> import_primitive(const PrimitiveSource& source, const GltfLoadOptions& options,
                              TextureSet& textures, GltfLoadReport& report,
                              ImportedGeometry& geometry) {
    const tinygltf::Model& model = source.model;
    const tinygltf::Primitive& primitive =
        model.meshes[static_cast<std::size_t>(source.mesh)]
            .primitives[static_cast<std::size_t>(source.primitive)];
    const std::string where = describe_primitive(model, source.mesh, source.primitive);
    const int mode =
        primitive.mode < 0 ? static_cast<int>(PrimitiveMode::Triangles) : primitive.mode;
    if (mode > static_cast<int>(PrimitiveMode::TriangleFan)) {
        return Error{where + ": mode " + std::to_string(mode) + " is not a glTF primitive mode"};
    }
    if (!is_triangle_mode(mode)) {
        ++report.primitives_skipped_points_or_lines;
        return true;
    }
    const int position_accessor = attribute(primitive, "POSITION");
    if (position_accessor < 0) {  // the specification says to skip such a primitive
        ++report.primitives_skipped_without_positions;
        return true;
    }
    const std::size_t limit = element_limit(options);

    Result<FloatElements> positions = read_float_accessor(
        model, position_accessor, {"POSITION of " + where, kVec3, false, limit});
    if (!positions) return positions.error();
    const std::size_t vertex_count = positions->count;

    TriangleList list;
    {
        std::vector<std::uint32_t> sequence;
        if (primitive.indices >= 0) {
            Result<std::vector<std::uint32_t>> indices = read_index_accessor(
                model, primitive.indices, "indices of " + where, vertex_count, limit);
            if (!indices) return indices.error();
            sequence = std::move(indices).value();
        } else {
            sequence.resize(vertex_count);
            std::iota(sequence.begin(), sequence.end(), 0u);
        }
        list = triangulate(mode, sequence);
    }
    report.indices_dropped_incomplete += list.dropped_incomplete;
    report.triangles_dropped_degenerate += list.dropped_degenerate;
    if (list.indices.empty()) return true;

    Result<std::vector<glm::vec3>> world_positions = to_world(*positions, source.world, where);
    if (!world_positions) return world_positions.error();
    positions = FloatElements{};

    // A mirroring transform turns counter-clockwise triangles clockwise: turn them back.
    const glm::dmat3 linear(source.world);
    const double determinant = glm::determinant(linear);
    if (determinant < 0.0) {
        for (std::size_t t = 0; t < list.indices.size(); t += 3) {
            std::swap(list.indices[t + 1], list.indices[t + 2]);
        }
    }

    Result<SurfaceLook> look = surface_look(model, primitive.material);
    if (!look) return Error{where + ": " + look.error().message};

    // Normals, per vertex of the file; or, for flat generated normals, one vertex per triangle
    // corner: origin[k] is then the file vertex behind output vertex k.
    const int normal_accessor = attribute(primitive, "NORMAL");
    const bool flat = normal_accessor < 0 && options.generated_normals == GeneratedNormals::Flat;
    std::vector<std::uint32_t> origin;
    std::vector<glm::vec3> normals;
    if (flat) {
        origin = std::move(list.indices);
        list.indices.resize(origin.size());
        std::iota(list.indices.begin(), list.indices.end(), 0u);
        normals.resize(origin.size());
        for (std::size_t t = 0; t < origin.size(); t += 3) {
            const glm::vec3 n =
                face_normal((*world_positions)[origin[t]], (*world_positions)[origin[t + 1]],
                            (*world_positions)[origin[t + 2]]);
            normals[t] = normals[t + 1] = normals[t + 2] = n;
        }
        report.normals_generated += origin.size();
    } else if (normal_accessor < 0) {
        normals = smooth_normals(*world_positions, list.indices);
        report.normals_generated += vertex_count;
    } else {
        Result<FloatElements> file_normals = read_float_accessor(
            model, normal_accessor, {"NORMAL of " + where, kVec3, false, limit});
        if (!file_normals) return file_normals.error();
        if (file_normals->count != vertex_count) {
            return count_mismatch("NORMAL", where, file_normals->count, vertex_count);
        }
        // Normals transform by the inverse transpose; a singular transform (a zero scale)
        // flattens the primitive, whose normals then come from its (zero-area) faces.
        const bool invertible = std::fabs(determinant) > 1e-300;
        const glm::dmat3 normal_matrix =
            invertible ? glm::inverseTranspose(linear) : glm::dmat3(0.0);
        normals.resize(vertex_count);
        std::vector<std::size_t> degenerate;
        for (std::size_t i = 0; i < vertex_count; ++i) {
            const float* n = &file_normals->values[3 * i];
            const glm::dvec3 transformed = normal_matrix * glm::dvec3(n[0], n[1], n[2]);
            const double length = glm::length(transformed);
            if (length > 1e-20 && std::isfinite(length)) {
                normals[i] = glm::vec3(transformed / length);
            } else {
                degenerate.push_back(i);
            }
        }
        if (!degenerate.empty()) {  // zero normals in the file, or a singular transform
            const std::vector<glm::vec3> generated = smooth_normals(*world_positions, list.indices);
            for (const std::size_t i : degenerate) normals[i] = generated[i];
            report.normals_generated += degenerate.size();
        }
    }

    // The base-colour texture and its coordinates.
    int scene_texture = -1;
    FloatElements uv;
    if (look->texture >= 0) {
        const std::string semantic = "TEXCOORD_" + std::to_string(look->texcoord_set);
        const int uv_accessor = attribute(primitive, semantic);
        if (uv_accessor < 0) {
            ++report.textures_without_texcoords;
        } else {
            Result<FloatElements> read = read_float_accessor(
                model, uv_accessor, {semantic + " of " + where, kVec2, true, limit});
            if (!read) return read.error();
            if (read->count != vertex_count)
                return count_mismatch(semantic, where, read->count, vertex_count);
            Result<int> texture = textures.use(look->texture);
            if (!texture) return Error{where + ": " + texture.error().message};
            scene_texture = *texture;
            uv = std::move(read).value();
        }
    }
    FloatElements colours;
    if (const int colour_accessor = attribute(primitive, "COLOR_0"); colour_accessor >= 0) {
        Result<FloatElements> read = read_float_accessor(
            model, colour_accessor, {"COLOR_0 of " + where, kColourTypes, true, limit});
        if (!read) return read.error();
        if (read->count != vertex_count)
            return count_mismatch("COLOR_0", where, read->count, vertex_count);
        colours = std::move(read).value();
    }

    const std::size_t output_count = flat ? origin.size() : vertex_count;
    GeometryBatch batch;
    batch.first_vertex = geometry.vertices.size();
    batch.vertex_count = static_cast<std::uint32_t>(output_count);  // <= element_limit()
    batch.first_index = geometry.indices.size();
    batch.index_count = list.indices.size();
    batch.texture = scene_texture;
    geometry.vertices.reserve(geometry.vertices.size() + output_count);
    geometry.texcoords.reserve(geometry.texcoords.size() + output_count);
    for (std::size_t k = 0; k < output_count; ++k) {
        const std::size_t from = flat ? origin[k] : k;
        // Linear, like COLOR_0; the renderer multiplies in the texture (forward_shading.glsl).
        glm::vec4 colour = look->base_color;
        if (!colours.values.empty()) {
            const float* c = &colours.values[from * colours.components];
            colour *= glm::vec4(c[0], c[1], c[2], colours.components == 4 ? c[3] : 1.0f);
        }
        glm::vec2 texcoord(0.0f);
        if (scene_texture >= 0) {
            texcoord = {uv.values[2 * from], uv.values[2 * from + 1]};
        }
        Vertex vertex;
        vertex.position = (*world_positions)[from];
        vertex.normal = normals[k];
        vertex.albedo_rgba8 = pack_rgba8(colour.r, colour.g, colour.b, colour.a);
        vertex.material_packed = look->material_packed;
        geometry.vertices.push_back(vertex);
        geometry.texcoords.push_back(texcoord);
    }
    // Counter-clockwise about the vertex normals (scene.h), as ChunkBuilder::add_triangle has
    // it: where a file's normals contradict its winding, the normals decide, since the renderer
    // culls by winding and shades by normals and the two must agree.
    const Vertex* batch_vertices = geometry.vertices.data() + batch.first_vertex;
    for (std::size_t t = 0; t < list.indices.size(); t += 3) {
        const Vertex& a = batch_vertices[list.indices[t]];
        const Vertex& b = batch_vertices[list.indices[t + 1]];
        const Vertex& c = batch_vertices[list.indices[t + 2]];
        const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
        if (glm::dot(face, a.normal + b.normal + c.normal) < 0.0f) {
            std::swap(list.indices[t + 1], list.indices[t + 2]);
        }
    }
    geometry.indices.insert(geometry.indices.end(), list.indices.begin(), list.indices.end());
    if (look->double_sided) add_back_faces(batch, geometry);
    geometry.batches.push_back(batch);
    return true;
}

}  // namespace monoplane::scenes::gltf
