#include "scenes/gltf/primitive_import.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
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

// What every step of one primitive's import reads: the primitive, the name messages give it,
// and the bounds on what its accessors may hold.
struct PrimitiveInput {
    const tinygltf::Model& model;
    const tinygltf::Primitive& primitive;
    std::string where;             // describe_primitive()
    std::size_t limit = 0;         // element_limit()
    std::size_t vertex_count = 0;  // POSITION's: every other attribute must have as many

    // A per-vertex attribute's elements, refused unless there is one per vertex.
    Result<FloatElements> read_per_vertex(int accessor, const std::string& semantic,
                                          std::span<const int> types, bool normalized) const {
        Result<FloatElements> read = read_float_accessor(
            model, accessor, {semantic + " of " + where, types, normalized, limit});
        MONOPLANE_TRY(read);
        if (read->count != vertex_count) {
            return count_mismatch(semantic, where, read->count, vertex_count);
        }
        return read;
    }
};

// The primitive's triangles as file vertex indices: its indices (or 0..n-1 without any) through
// its mode.
Result<TriangleList> read_triangles(const PrimitiveInput& in, int mode) {
    std::vector<std::uint32_t> sequence;
    if (in.primitive.indices >= 0) {
        Result<std::vector<std::uint32_t>> indices = read_index_accessor(
            in.model, in.primitive.indices, "indices of " + in.where, in.vertex_count, in.limit);
        MONOPLANE_TRY(indices);
        sequence = std::move(indices).value();
    } else {
        sequence.resize(in.vertex_count);
        std::iota(sequence.begin(), sequence.end(), 0u);
    }
    return triangulate(mode, sequence);
}

void reverse_winding(std::vector<std::uint32_t>& indices) {
    for (std::size_t t = 0; t < indices.size(); t += 3) std::swap(indices[t + 1], indices[t + 2]);
}

// The normals of the batch's vertices. Per vertex of the file; or, for flat generated normals,
// one vertex per triangle corner: origin[k] is then the file vertex behind output vertex k.
struct VertexNormals {
    std::vector<glm::vec3> normals;
    bool flat = false;
    std::vector<std::uint32_t> origin;  // flat only

    std::size_t file_vertex(std::size_t k) const { return flat ? origin[k] : k; }
};

// Flat generated normals: the triangles' corners become vertices of their own, numbered in
// order, each with its face's normal.
VertexNormals flat_normals(const std::vector<glm::vec3>& positions,
                           std::vector<std::uint32_t>& indices, GltfLoadReport& report) {
    VertexNormals result;
    result.flat = true;
    result.origin = std::move(indices);
    indices.resize(result.origin.size());
    std::iota(indices.begin(), indices.end(), 0u);
    const std::vector<std::uint32_t>& origin = result.origin;
    result.normals.resize(origin.size());
    for (std::size_t t = 0; t < origin.size(); t += 3) {
        const glm::vec3 n =
            face_normal(positions[origin[t]], positions[origin[t + 1]], positions[origin[t + 2]]);
        result.normals[t] = result.normals[t + 1] = result.normals[t + 2] = n;
    }
    report.normals_generated += origin.size();
    return result;
}

// The file's normals in the world. Normals transform by the inverse transpose; a singular
// transform (a zero scale) flattens the primitive, whose normals then come from its (zero-area)
// faces, as do zero normals in the file.
Result<std::vector<glm::vec3>> file_normals(const PrimitiveInput& in, int accessor,
                                            const glm::dmat3& linear,
                                            const std::vector<glm::vec3>& positions,
                                            const std::vector<std::uint32_t>& indices,
                                            GltfLoadReport& report) {
    Result<FloatElements> read = in.read_per_vertex(accessor, "NORMAL", kVec3, false);
    MONOPLANE_TRY(read);
    const bool invertible = std::fabs(glm::determinant(linear)) > 1e-300;
    const glm::dmat3 normal_matrix = invertible ? glm::inverseTranspose(linear) : glm::dmat3(0.0);
    std::vector<glm::vec3> normals(in.vertex_count);
    std::vector<std::size_t> degenerate;
    for (std::size_t i = 0; i < in.vertex_count; ++i) {
        const float* n = &read->values[3 * i];
        const glm::dvec3 transformed = normal_matrix * glm::dvec3(n[0], n[1], n[2]);
        const double length = glm::length(transformed);
        if (length > 1e-20 && std::isfinite(length)) {
            normals[i] = glm::vec3(transformed / length);
        } else {
            degenerate.push_back(i);
        }
    }
    if (!degenerate.empty()) {
        const std::vector<glm::vec3> generated = smooth_normals(positions, indices);
        for (const std::size_t i : degenerate) normals[i] = generated[i];
        report.normals_generated += degenerate.size();
    }
    return normals;
}

// NORMAL when the primitive has it; otherwise generated as the options ask.
Result<VertexNormals> vertex_normals(const PrimitiveInput& in, const GltfLoadOptions& options,
                                     const glm::dmat3& linear,
                                     const std::vector<glm::vec3>& positions,
                                     std::vector<std::uint32_t>& indices, GltfLoadReport& report) {
    const int accessor = attribute(in.primitive, "NORMAL");
    if (accessor < 0 && options.generated_normals == GeneratedNormals::Flat) {
        return flat_normals(positions, indices, report);
    }
    VertexNormals result;
    if (accessor < 0) {
        result.normals = smooth_normals(positions, indices);
        report.normals_generated += in.vertex_count;
        return result;
    }
    Result<std::vector<glm::vec3>> read =
        file_normals(in, accessor, linear, positions, indices, report);
    MONOPLANE_TRY(read);
    result.normals = std::move(read).value();
    return result;
}

// The base-colour texture (its index in the scene, or -1) and its coordinates.
struct BaseColourTexture {
    int scene_texture = -1;
    FloatElements uv;
};

// A texture without its TEXCOORD_n is left off (and counted), not refused.
Result<BaseColourTexture> read_base_colour_texture(const PrimitiveInput& in,
                                                   const SurfaceLook& look, TextureSet& textures,
                                                   GltfLoadReport& report) {
    BaseColourTexture result;
    if (look.texture < 0) return result;
    const std::string semantic = "TEXCOORD_" + std::to_string(look.texcoord_set);
    const int accessor = attribute(in.primitive, semantic);
    if (accessor < 0) {
        ++report.textures_without_texcoords;
        return result;
    }
    Result<FloatElements> uv = in.read_per_vertex(accessor, semantic, kVec2, true);
    MONOPLANE_TRY(uv);
    Result<int> texture = textures.use(look.texture);
    if (!texture) return Error{in.where + ": " + texture.error().message};
    result.scene_texture = *texture;
    result.uv = std::move(uv).value();
    return result;
}

// COLOR_0, or no elements without it.
Result<FloatElements> read_vertex_colours(const PrimitiveInput& in) {
    const int accessor = attribute(in.primitive, "COLOR_0");
    if (accessor < 0) return FloatElements{};
    return in.read_per_vertex(accessor, "COLOR_0", kColourTypes, true);
}

// Everything a batch's vertices are made from, per file vertex (normals: per output vertex).
struct VertexAttributes {
    std::vector<glm::vec3> positions;  // in the world
    VertexNormals normals;
    BaseColourTexture texture;
    FloatElements colours;  // COLOR_0; empty without
};

// Appends the batch's vertices and their texture coordinates.
void append_vertices(const VertexAttributes& attributes, const SurfaceLook& look,
                     std::size_t output_count, ImportedGeometry& geometry) {
    const FloatElements& colours = attributes.colours;
    const BaseColourTexture& texture = attributes.texture;
    geometry.vertices.reserve(geometry.vertices.size() + output_count);
    geometry.texcoords.reserve(geometry.texcoords.size() + output_count);
    for (std::size_t k = 0; k < output_count; ++k) {
        const std::size_t from = attributes.normals.file_vertex(k);
        // Linear, like COLOR_0; the renderer multiplies in the texture (forward_shading.glsl).
        // Alpha too: the factor's times COLOR_0's (a VEC3 colour is opaque), which masked and
        // blended chunks use and opaque ones ignore.
        glm::vec4 colour = look.base_color;
        if (!colours.values.empty()) {
            const float* c = &colours.values[from * colours.components];
            colour *= glm::vec4(c[0], c[1], c[2], colours.components == 4 ? c[3] : 1.0f);
        }
        glm::vec2 texcoord(0.0f);
        if (texture.scene_texture >= 0) {
            texcoord = {texture.uv.values[2 * from], texture.uv.values[2 * from + 1]};
        }
        Vertex vertex;
        vertex.position = attributes.positions[from];
        vertex.normal = attributes.normals.normals[k];
        vertex.albedo_rgba8 = pack_rgba8(colour.r, colour.g, colour.b, colour.a);
        vertex.material_packed = look.material_packed;
        geometry.vertices.push_back(vertex);
        geometry.texcoords.push_back(texcoord);
    }
}

// Counter-clockwise about the vertex normals (scene.h), as ChunkBuilder::add_triangle has it:
// where a file's normals contradict its winding, the normals decide, since the renderer culls by
// winding and shades by normals and the two must agree.
void orient_by_normals(const Vertex* vertices, std::vector<std::uint32_t>& indices) {
    for (std::size_t t = 0; t < indices.size(); t += 3) {
        const Vertex& a = vertices[indices[t]];
        const Vertex& b = vertices[indices[t + 1]];
        const Vertex& c = vertices[indices[t + 2]];
        const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
        if (glm::dot(face, a.normal + b.normal + c.normal) < 0.0f) {
            std::swap(indices[t + 1], indices[t + 2]);
        }
    }
}

// The primitive as one batch of geometry, its back faces too when its material is double-sided.
void append_batch(const VertexAttributes& attributes, const SurfaceLook& look,
                  std::vector<std::uint32_t>& indices, ImportedGeometry& geometry) {
    const std::size_t output_count =
        attributes.normals.flat ? attributes.normals.origin.size() : attributes.positions.size();
    GeometryBatch batch;
    batch.first_vertex = geometry.vertices.size();
    batch.vertex_count = static_cast<std::uint32_t>(output_count);  // <= element_limit()
    batch.first_index = geometry.indices.size();
    batch.index_count = indices.size();
    batch.texture = attributes.texture.scene_texture;
    batch.alpha_mode = look.alpha_mode;
    batch.alpha_cutoff = look.alpha_cutoff;
    append_vertices(attributes, look, output_count, geometry);
    orient_by_normals(geometry.vertices.data() + batch.first_vertex, indices);
    geometry.indices.insert(geometry.indices.end(), indices.begin(), indices.end());
    if (look.double_sided) add_back_faces(batch, geometry);
    geometry.batches.push_back(batch);
}

}  // namespace

std::string describe_primitive(const tinygltf::Model& model, int mesh, int primitive) {
    const std::string& name = model.meshes[static_cast<std::size_t>(mesh)].name;
    return (name.empty() ? "mesh " + std::to_string(mesh) : "mesh '" + name + "'") + " primitive " +
           std::to_string(primitive);
}

Result<void> import_primitive(const PrimitiveSource& source, const GltfLoadOptions& options,
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
        return Ok{};
    }
    const int position_accessor = attribute(primitive, "POSITION");
    if (position_accessor < 0) {  // the specification says to skip such a primitive
        ++report.primitives_skipped_without_positions;
        return Ok{};
    }
    PrimitiveInput in{model, primitive, where, element_limit(options)};

    Result<FloatElements> positions = read_float_accessor(
        model, position_accessor, {"POSITION of " + where, kVec3, false, in.limit});
    MONOPLANE_TRY(positions);
    in.vertex_count = positions->count;

    Result<TriangleList> triangles = read_triangles(in, mode);
    MONOPLANE_TRY(triangles);
    TriangleList list = std::move(triangles).value();
    report.indices_dropped_incomplete += list.dropped_incomplete;
    report.triangles_dropped_degenerate += list.dropped_degenerate;
    if (list.indices.empty()) return Ok{};

    VertexAttributes attributes;
    {
        Result<std::vector<glm::vec3>> world = to_world(*positions, source.world, where);
        MONOPLANE_TRY(world);
        attributes.positions = std::move(world).value();
    }
    positions = FloatElements{};  // the file's copy is no longer needed

    // A mirroring transform turns counter-clockwise triangles clockwise: turn them back.
    const glm::dmat3 linear(source.world);
    if (glm::determinant(linear) < 0.0) reverse_winding(list.indices);

    Result<SurfaceLook> look = surface_look(model, primitive.material);
    if (!look) return Error{where + ": " + look.error().message};
    Result<VertexNormals> normals =
        vertex_normals(in, options, linear, attributes.positions, list.indices, report);
    MONOPLANE_TRY(normals);
    attributes.normals = std::move(normals).value();
    Result<BaseColourTexture> texture = read_base_colour_texture(in, *look, textures, report);
    MONOPLANE_TRY(texture);
    attributes.texture = std::move(texture).value();
    Result<FloatElements> colours = read_vertex_colours(in);
    MONOPLANE_TRY(colours);
    attributes.colours = std::move(colours).value();

    append_batch(attributes, *look, list.indices, geometry);
    return Ok{};
}

}  // namespace monoplane::scenes::gltf
