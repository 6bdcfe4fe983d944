#include "tests/gpu/alpha_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "tests/unit/gltf_test_files.h"
#include "tests/unit/png_bytes.h"

namespace monoplane::testing {
namespace {

using nlohmann::json;
using scenes::testing::TestGltf;

// glTF's sampler enumerations.
constexpr int kLinear = 9729;
constexpr int kLinearMipmapLinear = 9987;
constexpr int kClampToEdge = 33071;

// A kAlphaTextureSize square RGBA image, texel (column, row) given by `texel`.
template <class Texel>
std::vector<unsigned char> image(Texel texel) {
    std::vector<unsigned char> rgba;
    rgba.reserve(4 * kAlphaTextureSize * kAlphaTextureSize);
    for (int row = 0; row < kAlphaTextureSize; ++row) {
        for (int column = 0; column < kAlphaTextureSize; ++column) {
            const std::array<unsigned char, 4> value = texel(column, row);
            rgba.insert(rgba.end(), value.begin(), value.end());
        }
    }
    return rgba;
}

unsigned char gradient_texel_alpha(int column) {
    return static_cast<unsigned char>(
        std::lround(255.0 * (column + 0.5) / static_cast<double>(kAlphaTextureSize)));
}

std::vector<unsigned char> checker_image() {
    constexpr int kCellTexels = kAlphaTextureSize / kCheckerCells;
    return image([](int column, int row) -> std::array<unsigned char, 4> {
        const bool opaque = (column / kCellTexels + row / kCellTexels) % 2 == 0;
        return {kCheckerTexel[0], kCheckerTexel[1], kCheckerTexel[2],
                static_cast<unsigned char>(opaque ? 255 : 0)};
    });
}

std::vector<unsigned char> gradient_image(const std::array<std::uint8_t, 3>& colour) {
    return image([&colour](int column, int) -> std::array<unsigned char, 4> {
        return {colour[0], colour[1], colour[2], gradient_texel_alpha(column)};
    });
}

void write_texture(const std::filesystem::path& path, const std::vector<unsigned char>& rgba) {
    write_png(path, kAlphaTextureSize, kAlphaTextureSize, rgba);
}

json factor(const glm::vec4& colour) {
    return json::array({colour.r, colour.g, colour.b, colour.a});
}

// A material: metallic 0, roughness 1; texture -1 for none; alpha_mode "OPAQUE", "MASK" or
// "BLEND"; cutoff < 0 leaves alphaCutoff out.
json material(const std::string& name, const glm::vec4& colour, int texture,
              const std::string& alpha_mode, double cutoff = -1.0, bool double_sided = false) {
    json pbr = {
        {"baseColorFactor", factor(colour)}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}};
    if (texture >= 0) pbr["baseColorTexture"] = {{"index", texture}};
    json result = {{"name", name}, {"pbrMetallicRoughness", pbr}, {"alphaMode", alpha_mode}};
    if (cutoff >= 0.0) result["alphaCutoff"] = cutoff;
    if (double_sided) result["doubleSided"] = true;
    return result;
}

// A node with one mesh of one primitive: the quad's two triangles (counter-clockwise about its
// normal), normals and, when textured, TEXCOORD_0.
void add_quad(TestGltf& file, const AlphaQuad& quad, int material_index, bool textured) {
    const glm::vec3 normal = quad.normal();
    const std::vector<glm::vec2> uv = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    std::vector<glm::vec3> positions;
    for (const glm::vec2& c : uv) positions.push_back(quad.at(c));
    json attributes = {{"POSITION", file.add_positions(positions)},
                       {"NORMAL", file.add_positions({normal, normal, normal, normal})}};
    if (textured) attributes["TEXCOORD_0"] = file.add_vec2(uv);
    // (0,0), (0,1), (1,0): cross(v_edge, u_edge) is the normal; then (0,1), (1,1), (1,0).
    const int indices = file.add_indices({0, 1, 3, 1, 2, 3});
    const int mesh = file.add_mesh(attributes, indices, 4, material_index, quad.name);
    file.add_node({{"mesh", mesh}, {"name", quad.name}});
}

// The materials and nodes both scenes share: glTF camera, sampler, ground and backdrop.
TestGltf base_scene() {
    TestGltf file;
    file.json["cameras"] = {{{"type", "perspective"},
                             {"perspective", {{"yfov", 1.2}, {"znear", 0.05}, {"zfar", 200.0}}}}};
    file.add_node({{"name", "eye"},
                   {"camera", 0},
                   {"translation", {kAlphaSceneEye.x, kAlphaSceneEye.y, kAlphaSceneEye.z}}});
    file.json["samplers"] = {{{"magFilter", kLinear},
                              {"minFilter", kLinearMipmapLinear},
                              {"wrapS", kClampToEdge},
                              {"wrapT", kClampToEdge}}};
    file.json["materials"] = {material("ground", kAlphaGroundColour, -1, "OPAQUE"),
                              material("backdrop", kAlphaBackdropColour, -1, "OPAQUE")};
    add_quad(file, kAlphaGround, 0, false);
    add_quad(file, kAlphaBackdrop, 1, false);
    return file;
}

int add_material(TestGltf& file, const json& material_json) {
    file.json["materials"].push_back(material_json);
    return static_cast<int>(file.json["materials"].size()) - 1;
}

}  // namespace

glm::vec3 AlphaQuad::at(glm::vec2 uv) const {
    return corner + uv.x * u_edge + uv.y * v_edge;
}

glm::vec3 AlphaQuad::normal() const {
    return glm::normalize(glm::cross(v_edge, u_edge));
}

bool checker_opaque(glm::vec2 uv) {
    const auto cell = [](float t) {
        return std::clamp(static_cast<int>(std::floor(t * kCheckerCells)), 0, kCheckerCells - 1);
    };
    return (cell(uv.x) + cell(uv.y)) % 2 == 0;
}

float gradient_alpha(glm::vec2 uv) {
    return std::clamp(uv.x, 0.0f, 1.0f);
}

std::filesystem::path write_fence_scene(const std::filesystem::path& dir,
                                        const FenceOptions& options) {
    write_texture(dir / "fence_checker.png", checker_image());
    write_texture(dir / "alpha_gradient.png", gradient_image(kGradientTexel));
    TestGltf file = base_scene();
    file.json["images"] = {{{"uri", "fence_checker.png"}}, {{"uri", "alpha_gradient.png"}}};
    file.json["textures"] = {{{"sampler", 0}, {"source", 0}}, {{"sampler", 0}, {"source", 1}}};
    const std::string mode = options.masked ? "MASK" : "OPAQUE";
    const glm::vec4 white(1.0f);
    const int checker = add_material(file, material("fence_checker", white, 0, mode));
    const int gradient =
        add_material(file, material("fence_gradient", white, 1, mode, options.gradient_cutoff));
    const int high = add_material(file, material("fence_high", white, 0, mode, -1.0, true));
    add_quad(file, kFenceChecker, checker, true);
    add_quad(file, kFenceGradient, gradient, true);
    add_quad(file, kFenceHigh, high, true);
    char cutoff[32];
    std::snprintf(cutoff, sizeof cutoff, "%.3f", static_cast<double>(options.gradient_cutoff));
    const std::filesystem::path path =
        dir / ("fence_" + std::string(options.masked ? "mask" : "opaque") + "_" + cutoff + ".gltf");
    file.write_gltf(path);
    return path;
}

std::filesystem::path write_pane_scene(const std::filesystem::path& dir,
                                       const PaneOptions& options) {
    TestGltf file = base_scene();
    if (options.with_panes) {
        write_texture(dir / "pane_gradient.png", gradient_image({255, 255, 255}));
        file.json["images"] = {{{"uri", "pane_gradient.png"}}};
        file.json["textures"] = {{{"sampler", 0}, {"source", 0}}};
        const std::string mode = options.blended ? "BLEND" : "OPAQUE";
        for (const AlphaPane& pane : kAlphaPanes) {
            const int index = add_material(
                file, material(pane.quad.name, pane.colour, pane.textured ? 0 : -1, mode));
            add_quad(file, pane.quad, index, pane.textured);
        }
    }
    const std::string variant =
        !options.with_panes ? "empty" : (options.blended ? "blend" : "opaque");
    const std::filesystem::path path = dir / ("panes_" + variant + ".gltf");
    file.write_gltf(path);
    return path;
}

glm::vec3 ground_shadow(const glm::vec3& point, const glm::vec3& sun_direction) {
    return point - (point.y / sun_direction.y) * sun_direction;
}

}  // namespace monoplane::testing
