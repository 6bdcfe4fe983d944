// The scene model shared by generators, culling and the renderer.
// World frame: metres, +y up; a participant at a scene's default viewpoint looks down -z.
// Triangles wind counter-clockwise seen from the side their vertex normals point to (right-handed:
// cross(b - a, c - a) agrees with the normals), so back-face culling may be enabled.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "rig/pose.h"

namespace monoplane::scenes {

// Imported: read from a file (scenes/gltf/load_gltf.h); generate_scene() cannot make one.
enum class SceneId { Beams, Landscape, Spheres, Imported };

// test: a few ten thousand triangles (unit and GPU tests); low/medium: interactive on llvmpipe;
// high/ultra: benchmarks on a GPU, millions of triangles.
enum class Detail { Test, Low, Medium, High, Ultra };

// One vertex as uploaded to the GPU (32 bytes; the shaders declare the same layout).
struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;               // unit length
    std::uint32_t albedo_rgba8;     // linear albedo, R in the low byte
    std::uint32_t material_packed;  // see pack_material()
};
static_assert(sizeof(Vertex) == 32, "the vertex layout is shared with the shaders");

// Surface response: roughness and specular reflectance in [0, 1], pattern selects a procedural
// albedo modulation in the shader (0: none, 1: terrain noise, 2: stripes along beams).
// Packed as forward.frag reads it: bits 0-7 roughness * 255, bits 8-15 specular * 255,
// bits 16-23 pattern, bits 24-31 zero.
struct Material {
    float roughness = 0.6f;
    float specular = 0.04f;
    std::uint8_t pattern = 0;
};
std::uint32_t pack_material(const Material& material);
Material unpack_material(std::uint32_t packed);
// Components in [0, 1] (clamped) to R8G8B8A8_UNORM with R in the low byte.
std::uint32_t pack_rgba8(float r, float g, float b, float a = 1.0f);

struct Aabb {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
};

// Per-chunk routing hints for hybrid rendering (papers/003, "Force Mono"): a chunk whose bounds
// reach into the near region although its pixels never do (far terrain with a large box) may be
// forced to the mono camera C; a chunk that never reaches beyond the mono plane may be forced to
// the eyes. ChunkRouting says where flagged geometry lies, so the renderer honours a flag only
// for mono planes where it cannot remove visible pixels (the sky is always C's in hybrid modes).
enum ChunkFlags : std::uint32_t { kChunkNone = 0, kChunkForceMono = 1, kChunkForceStereo = 2 };

struct ChunkRouting {
    // kChunkForceMono chunks lie outside the vertical cylinder of this radius about the world's
    // y axis (0: no chunk is flagged).
    float force_mono_outside_radius = 0.0f;
    // kChunkForceStereo chunks lie inside the sphere of this radius about force_stereo_centre
    // (0: no chunk is flagged).
    float force_stereo_inside_radius = 0.0f;
    glm::vec3 force_stereo_centre{0.0f};
};

// How a chunk's surface covers what lies behind it (glTF's material.alphaMode). Its alpha is the
// vertex's albedo alpha (base-colour factor times vertex colour) times the base-colour texture's.
// kOpaque ignores alpha; kMask drops the fragments whose alpha is below Chunk::alpha_cutoff and
// draws the rest opaque (cut-outs: leaves, fences, grilles); kBlend draws after the opaque
// geometry, back to front, over what lies behind with weight alpha (glass, water), writing no
// depth. Procedural scenes are opaque throughout.
enum class AlphaMode : std::uint8_t { kOpaque = 0, kMask = 1, kBlend = 2 };

// A contiguous index range with its bounds: the unit of culling and of indirect draws.
struct Chunk {
    std::uint32_t first_index = 0;
    std::uint32_t index_count = 0;
    std::int32_t vertex_offset = 0;
    Aabb bounds;
    std::uint32_t flags = kChunkNone;
    // Index into Scene::textures of the base-colour texture every triangle of the chunk uses, or
    // -1 for none: a chunk never mixes textures, so one draw binds one texture.
    std::int32_t texture = -1;
    // A chunk never mixes alpha modes or cut-offs (one pipeline and one cut-off per draw).
    AlphaMode alpha_mode = AlphaMode::kOpaque;
    float alpha_cutoff = 0.5f;  // kMask only: glTF's alphaCutoff (default 0.5)
};

// How texture coordinates outside [0, 1] fold back (the glTF sampler's wrapS / wrapT).
enum class TextureWrap : std::uint8_t { Repeat, ClampToEdge, MirroredRepeat };

// A decoded base-colour image of an imported scene. The forward pass multiplies the vertex's
// albedo (base-colour factor times vertex colour) by the texture, sampled trilinearly through an
// sRGB format at Scene::texcoords (renderer/passes/shared/scene_textures.h).
struct SceneTexture {
    std::string name;  // the glTF image's name or file, for messages
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    // width * height RGBA8 texels, colour sRGB-encoded (sample through an _SRGB format), alpha
    // linear; row 0 is the top of the image, where texture coordinate v = 0 (glTF's convention).
    std::vector<std::uint8_t> rgba8_srgb;
    TextureWrap wrap_u = TextureWrap::Repeat;
    TextureWrap wrap_v = TextureWrap::Repeat;
};

struct Viewpoint {
    std::string name;  // "default" is where a participant stands; "bench-*" for the benchmark
    rig::Pose head;
};

// A named head pose at position, turned by yaw (positive: left) then pitch (positive: up).
Viewpoint make_viewpoint(std::string name, const glm::dvec3& position, double yaw_degrees = 0.0,
                         double pitch_degrees = 0.0);

struct Lighting {
    glm::vec3 sun_direction{0.3f, 0.8f, 0.4f};  // unit vector pointing towards the sun
    glm::vec3 sun_radiance{3.0f, 2.85f, 2.6f};
    glm::vec3 sky_zenith{0.18f, 0.36f, 0.75f};
    glm::vec3 sky_horizon{0.70f, 0.80f, 0.92f};
    glm::vec3 ground_albedo{0.30f, 0.28f, 0.25f};  // below the horizon, for reflections
};

struct Scene {
    SceneId id = SceneId::Spheres;
    std::string name;  // "beams", "landscape", "spheres"; an imported scene's file stem
    Detail detail = Detail::Test;
    std::uint64_t seed = 0;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;  // chunk-relative: add Chunk::vertex_offset
    std::vector<Chunk> chunks;
    // Base-colour texture coordinates parallel to vertices, or empty when no chunk has a texture
    // (procedural scenes never have one); (0, 0) at the vertices of untextured chunks.
    std::vector<glm::vec2> texcoords;
    std::vector<SceneTexture> textures;  // what Chunk::texture indexes
    Aabb bounds;
    std::vector<Viewpoint> viewpoints;  // the first is "default"
    Lighting lighting;
    ChunkRouting routing;

    std::size_t triangle_count() const { return indices.size() / 3; }
    // The viewpoint with this name, or nullptr.
    const Viewpoint* find_viewpoint(const std::string& name) const;
};

}  // namespace monoplane::scenes
