// glTF scenes for the tests of alpha modes (MASK and BLEND, scenes::AlphaMode), written by the
// tests themselves: a fence of alpha-masked quads and a set of blended panes, each over an opaque
// ground and backdrop. The geometry is exported below, so a test can project world points and
// know which pixels show a cut-out hole, a pane or what lies behind it.
//
// World frame as scenes/scene.h: metres, +y up. Both files have a glTF camera at kAlphaSceneEye
// looking down -z, which becomes the scenes' "default" viewpoint. Lighting is scenes::Lighting's
// default (glTF has no sun): ground_shadow() says where a point's shadow falls.
//
// Textures: kAlphaTextureSize square RGBA PNGs beside the .gltf, colour sRGB-encoded, alpha
// linear, sampled with CLAMP_TO_EDGE and trilinear filtering. Texture coordinates as glTF has
// them: (0, 0) is the top-left texel of the image (row 0, v = 0), u grows to the right of the
// image and v downwards. On every quad here the image reads upright from the front: v = 0 is the
// quad's top edge (vertical quads) or its far edge seen from the eye (the horizontal quad).
//
// Plain CPU code (nlohmann-json, stb_image_write): the library monoplane_alpha_scenes, defined in
// tests/CMakeLists.txt so that unit tests link it with or without Vulkan.
//
// When may this be called: any thread, any time; each writer writes only into `dir`, which must
// exist.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace monoplane::testing {

// A flat rectangle and its texture coordinates: the corner at (u, v) = (0, 0), and the edges to
// the corners at (1, 0) and (0, 1). Its front faces normal() (= cross(v_edge, u_edge),
// normalised); its triangles wind counter-clockwise seen from there.
struct AlphaQuad {
    const char* name;
    glm::vec3 corner;
    glm::vec3 u_edge;
    glm::vec3 v_edge;

    // The world point at texture coordinate uv (uv in [0, 1]^2 lies on the quad).
    glm::vec3 at(glm::vec2 uv) const;
    glm::vec3 centre() const { return at({0.5f, 0.5f}); }
    glm::vec3 normal() const;
};

// Where both scenes' glTF camera (the "default" viewpoint) stands, looking down -z.
inline constexpr glm::vec3 kAlphaSceneEye{0.0f, 1.6f, 0.0f};

// Opaque in both scenes, untextured. The ground: y = 0, x and z in [-40, 40], normal +y, grey.
inline constexpr AlphaQuad kAlphaGround{
    "ground", {-40.0f, 0.0f, -40.0f}, {80.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 80.0f}};
inline constexpr glm::vec4 kAlphaGroundColour{0.5f, 0.5f, 0.5f, 1.0f};  // linear baseColorFactor
// The backdrop: z = -40, x in [-40, 40], y in [0, 40], facing +z (towards the eye).
inline constexpr AlphaQuad kAlphaBackdrop{
    "backdrop", {-40.0f, 40.0f, -40.0f}, {80.0f, 0.0f, 0.0f}, {0.0f, -40.0f, 0.0f}};
inline constexpr glm::vec4 kAlphaBackdropColour{0.2f, 0.5f, 0.3f, 1.0f};

// Both textures are kAlphaTextureSize x kAlphaTextureSize texels.
inline constexpr int kAlphaTextureSize = 64;

// The checker texture (fence_checker.png): colour kCheckerTexel everywhere, alpha 255 on the
// cells where checker_opaque() holds and 0 on the others, kCheckerCells x kCheckerCells cells of
// kAlphaTextureSize / kCheckerCells texels each.
inline constexpr int kCheckerCells = 8;
inline constexpr std::array<std::uint8_t, 3> kCheckerTexel{230, 140, 40};  // sRGB-encoded
// Whether texture coordinate uv (in [0, 1]^2) lies on an opaque cell: cell column
// floor(u * kCheckerCells) plus cell row floor(v * kCheckerCells) is even. The cell at uv (0, 0),
// the top-left of the image, is opaque.
bool checker_opaque(glm::vec2 uv);

// The gradient texture (alpha_gradient.png): colour kGradientTexel everywhere, alpha of texel
// column i (from the image's left) round(255 * (i + 0.5) / kAlphaTextureSize), the same on
// every row: bilinear filtering between texel centres gives alpha(u) = u within 1/255 (and
// clamps to the edge columns' alpha in the outer half texel).
inline constexpr std::array<std::uint8_t, 3> kGradientTexel{40, 110, 230};  // sRGB-encoded
float gradient_alpha(glm::vec2 uv);  // u, clamped as the sampler does, in [0, 1]

// ---- The fence scene (write_fence_scene) ----

// Masked quads (alphaMode MASK; metallic 0, roughness 1; baseColorFactor white, opaque, so the
// texture's alpha is the surface's alpha):
// - kFenceChecker: the checker texture, alphaCutoff left out (0.5), single-sided, facing +z.
//   Each cell is 0.5 m wide and 0.25 m tall.
inline constexpr AlphaQuad kFenceChecker{
    "fence_checker", {-2.0f, 2.75f, -4.0f}, {4.0f, 0.0f, 0.0f}, {0.0f, -2.0f, 0.0f}};
// - kFenceGradient: the gradient texture, alphaCutoff FenceOptions::gradient_cutoff (always
//   written), single-sided, facing +z: with cut-off c, the part u < c (its left, x < corner.x +
//   c * 1.6 m) is cut away.
inline constexpr AlphaQuad kFenceGradient{
    "fence_gradient", {2.2f, 2.75f, -4.0f}, {1.6f, 0.0f, 0.0f}, {0.0f, -2.0f, 0.0f}};
// - kFenceHigh: horizontal at y = 3.5 above the fence, x in [-1, 1], z in [-5, -3], the checker
//   texture, double-sided (its underside is seen from the eye), normal +y. v = 0 is its far edge
//   (z = -5), u = 0 its left (x = -1). Its shadow on the ground has the checker's holes.
inline constexpr AlphaQuad kFenceHigh{
    "fence_high", {-1.0f, 3.5f, -5.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 2.0f}};

struct FenceOptions {
    float gradient_cutoff = 0.5f;  // kFenceGradient's alphaCutoff
    // false: the three quads are OPAQUE (the same textures, their alpha ignored), a reference
    // for what the cut-outs remove.
    bool masked = true;
};

// Writes fence_<mask|opaque>_<cutoff with 3 decimals>.gltf (buffer embedded) and its textures
// fence_checker.png and alpha_gradient.png into dir; returns the .gltf's path. Materials, one per
// quad, named as it: ground, backdrop (OPAQUE), then kFenceChecker, kFenceGradient, kFenceHigh.
// Loaded with the default options, the masked scene has one opaque chunk (ground and backdrop),
// one masked chunk with the checker texture and cut-off 0.5 (fence and high quad, 6 triangles:
// the high quad's back faces too) and one with the gradient texture and cut-off
// gradient_cutoff; the opaque variant has three opaque chunks (one per texture, and none).
std::filesystem::path write_fence_scene(const std::filesystem::path& dir,
                                        const FenceOptions& options = {});

// ---- The pane scene (write_pane_scene) ----

// A pane facing +z (single-sided), its linear baseColorFactor (alpha included) and whether it
// carries the gradient texture (alpha_gradient.png, with kGradientTexel's colour replaced by
// white: pane_gradient.png, so its colour is the factor's and its alpha gradient_alpha(uv) times
// the factor's).
struct AlphaPane {
    AlphaQuad quad;
    glm::vec4 colour;
    bool textured;
};

// Seen from kAlphaSceneEye looking down -z (tangents of the angles: x / distance, (y - 1.6) /
// distance), the panes lie within 37 degrees of the view axis: near_red x in [-0.57, -0.23],
// y in [-0.17, 0.17]; behind_near x in [-0.33, -0.08], y in [-0.13, 0.13], so near_red covers
// its part x < -0.23 and leaves x > -0.23 uncovered; far_blue x in [0, 0.21], y in [-0.11, 0.11];
// gradient x in [0.45, 0.75], y in [-0.15, 0.15]. Only near_red and behind_near overlap.
inline constexpr AlphaPane kNearRedPane{
    {"near_red", {-1.7f, 2.1f, -3.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, -1.0f, 0.0f}},
    {0.9f, 0.1f, 0.1f, 0.5f},
    false};
inline constexpr AlphaPane kBehindNearPane{
    {"behind_near", {-1.95f, 2.35f, -6.0f}, {1.5f, 0.0f, 0.0f}, {0.0f, -1.5f, 0.0f}},
    {0.9f, 0.9f, 0.1f, 0.6f},
    false};
inline constexpr AlphaPane kFarBluePane{
    {"far_blue", {0.0f, 3.1f, -14.0f}, {3.0f, 0.0f, 0.0f}, {0.0f, -3.0f, 0.0f}},
    {0.1f, 0.2f, 0.9f, 0.3f},
    false};
inline constexpr AlphaPane kGradientPane{
    {"gradient", {2.25f, 2.35f, -5.0f}, {1.5f, 0.0f, 0.0f}, {0.0f, -1.5f, 0.0f}},
    {0.2f, 0.9f, 0.2f, 1.0f},
    true};
// In the order the file's materials and meshes list them (after ground and backdrop).
inline constexpr std::array<AlphaPane, 4> kAlphaPanes{kNearRedPane, kBehindNearPane, kFarBluePane,
                                                      kGradientPane};

struct PaneOptions {
    // false: the panes are OPAQUE (alpha ignored), the reference for each pane's own colour.
    bool blended = true;
    // false: ground and backdrop only, the reference for what lies behind the panes.
    bool with_panes = true;
};

// Writes panes_<blend|opaque|empty>.gltf (buffer embedded) and, with panes, pane_gradient.png
// into dir; returns the .gltf's path. Materials: ground, backdrop, then one per pane in
// kAlphaPanes's order, named as the pane. Loaded with the default options, the blended scene has
// one opaque chunk (ground and backdrop) and one BLEND chunk per pane (blended chunks never share
// a primitive instance: the renderer orders them back to front as wholes); the opaque variant
// has two opaque chunks (untextured, and the gradient pane's).
std::filesystem::path write_pane_scene(const std::filesystem::path& dir,
                                       const PaneOptions& options = {});

// Where the sun's shadow of `point` falls on the ground (y = 0), for a sun in direction
// sun_direction (towards the sun, as scenes::Lighting has it; its y must be positive).
glm::vec3 ground_shadow(const glm::vec3& point, const glm::vec3& sun_direction);

}  // namespace monoplane::testing
