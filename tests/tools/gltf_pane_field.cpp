// Writes a scene for benchmarking blended surfaces (alphaMode BLEND): `gltf_pane_field [--panes
// N] [--opaque] [--out FILE.gltf]` writes a .gltf (buffer embedded as base64) with an opaque grey
// ground (y = 0, x and z in [-100, 100]), an opaque green backdrop (z = -90, x in [-100, 100], y
// in [0, 50], facing +z) and a field of N (default 400) coloured square panes, each its own
// material, mesh and node (so each blended pane becomes a chunk of its own), vertical and
// single-sided, facing +z towards a glTF camera at (0, 1.6, 0) looking down -z (the scene's
// "default" viewpoint). Pane i stands at depth d (its plane is z = -d), d log-uniform in [1.5,
// 60] m (as many panes per octave of depth: 1.5-3, 3-6, ...), side 1-2 m, centre x within
// +-0.8 d, centre height 0.5-3 m (raised where a pane would reach into the ground), colour a
// random hue, alpha 0.3-0.6. Positions come from a fixed seed (std::mt19937, its raw output:
// the same file on every platform). `--opaque` writes the same panes with alphaMode OPAQUE: what
// the same geometry costs drawn opaque (they then share chunks of up to 2,048 triangles: 400
// panes make one). Without --out it writes /tmp/pane_field_<blend|opaque>_<N>.gltf. Prints what
// it wrote and how many panes lie beyond a few mono-plane distances. Not a test; write to /tmp,
// not the tree. docs/benchmarks.md ("Blended surfaces") benchmarks the two.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "tests/unit/gltf_test_files.h"

namespace {

using monoplane::scenes::testing::TestGltf;
using nlohmann::json;

constexpr float kEyeHeight = 1.6f;
constexpr float kNearestDepth = 1.5f;
constexpr float kFarthestDepth = 60.0f;
constexpr std::uint32_t kSeed = 20261204;

// A flat rectangle: corner at texture coordinate (0, 0), edges to (1, 0) and (0, 1); its front
// faces cross(v_edge, u_edge).
struct Quad {
    glm::vec3 corner;
    glm::vec3 u_edge;
    glm::vec3 v_edge;
};

// Uniform in [0, 1) from the generator's raw 32 bits (the standard distributions differ between
// standard libraries; this does not).
float unit(std::mt19937& random) {
    return static_cast<float>(random() >> 8) * (1.0f / 16777216.0f);
}

float between(std::mt19937& random, float low, float high) {
    return low + (high - low) * unit(random);
}

// A hue on the colour wheel at full saturation, linear RGB, kept away from black.
glm::vec3 hue(float h) {
    const float x = 6.0f * h;
    const auto channel = [x](float offset) {
        const float t = std::fmod(x + offset, 6.0f);
        return std::clamp(std::abs(t - 3.0f) - 1.0f, 0.0f, 1.0f);
    };
    return 0.1f + 0.8f * glm::vec3(channel(0.0f), channel(4.0f), channel(2.0f));
}

json material(const std::string& name, const glm::vec4& colour, const std::string& alpha_mode) {
    return {{"name", name},
            {"pbrMetallicRoughness",
             {{"baseColorFactor", {colour.r, colour.g, colour.b, colour.a}},
              {"metallicFactor", 0.0},
              {"roughnessFactor", 1.0}}},
            {"alphaMode", alpha_mode}};
}

// A node with one mesh of one primitive: the quad's two triangles (counter-clockwise about its
// normal) and normals, with a material of its own.
void add_quad(TestGltf& file, const std::string& name, const Quad& quad,
              const json& material_json) {
    file.json["materials"].push_back(material_json);
    const int material_index = static_cast<int>(file.json["materials"].size()) - 1;
    const glm::vec3 normal = glm::normalize(glm::cross(quad.v_edge, quad.u_edge));
    const std::vector<glm::vec3> positions = {quad.corner, quad.corner + quad.v_edge,
                                              quad.corner + quad.u_edge + quad.v_edge,
                                              quad.corner + quad.u_edge};
    const json attributes = {{"POSITION", file.add_positions(positions)},
                             {"NORMAL", file.add_positions({normal, normal, normal, normal})}};
    const int indices = file.add_indices({0, 1, 3, 1, 2, 3});
    const int mesh = file.add_mesh(attributes, indices, 4, material_index, name);
    file.add_node({{"mesh", mesh}, {"name", name}});
}

int write(const std::string& path, int panes, bool opaque) {
    TestGltf file;
    file.json["cameras"] = {{{"type", "perspective"},
                             {"perspective", {{"yfov", 1.2}, {"znear", 0.05}, {"zfar", 300.0}}}}};
    file.add_node({{"name", "eye"}, {"camera", 0}, {"translation", {0.0f, kEyeHeight, 0.0f}}});
    file.json["materials"] = json::array();
    add_quad(file, "ground", {{-100.0f, 0.0f, -100.0f}, {200.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 200.0f}},
             material("ground", {0.5f, 0.5f, 0.5f, 1.0f}, "OPAQUE"));
    add_quad(file, "backdrop",
             {{-100.0f, 50.0f, -90.0f}, {200.0f, 0.0f, 0.0f}, {0.0f, -50.0f, 0.0f}},
             material("backdrop", {0.2f, 0.5f, 0.3f, 1.0f}, "OPAQUE"));

    std::mt19937 random(kSeed);
    const std::array<float, 3> planes = {3.0f, 8.0f, 16.0f};
    std::array<int, 3> beyond{};
    const float log_near = std::log(kNearestDepth);
    const float log_far = std::log(kFarthestDepth);
    for (int i = 0; i < panes; ++i) {
        const float depth = std::exp(between(random, log_near, log_far));
        const float side = between(random, 1.0f, 2.0f);
        const float x = between(random, -0.8f, 0.8f) * depth;
        const float y = std::max(between(random, 0.5f, 3.0f), 0.5f * side + 0.05f);
        const glm::vec3 rgb = hue(unit(random));
        const float alpha = between(random, 0.3f, 0.6f);
        const std::string name = "pane" + std::to_string(i);
        // Top-left corner seen from the eye; u to the right, v down: the front faces +z.
        add_quad(
            file, name,
            {{x - 0.5f * side, y + 0.5f * side, -depth}, {side, 0.0f, 0.0f}, {0.0f, -side, 0.0f}},
            material(name, {rgb, alpha}, opaque ? "OPAQUE" : "BLEND"));
        for (std::size_t p = 0; p < planes.size(); ++p)
            if (depth > planes[p]) ++beyond[p];
    }
    file.write_gltf(path);
    std::printf(
        "wrote %s: ground (200 x 200 m), backdrop (z = -90 m) and %d %s panes (sides 1-2 m, "
        "alpha 0.3-0.6, depths %.1f-%.0f m log-uniform, seed %u), glTF camera at (0, %.1f, 0) "
        "looking down -z; panes deeper than 3 / 8 / 16 m: %d / %d / %d\n",
        path.c_str(), panes, opaque ? "OPAQUE" : "BLEND", static_cast<double>(kNearestDepth),
        static_cast<double>(kFarthestDepth), kSeed, static_cast<double>(kEyeHeight), beyond[0],
        beyond[1], beyond[2]);
    return 0;
}

int run(int argc, char** argv) {
    const std::string usage = "usage: gltf_pane_field [--panes N] [--opaque] [--out FILE.gltf]";
    int panes = 400;
    bool opaque = false;
    std::string out;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--opaque") {
            opaque = true;
        } else if (arg == "--panes" && i + 1 < argc) {
            char* end = nullptr;
            const long value = std::strtol(argv[++i], &end, 10);
            if (*end != '\0' || value < 0 || value > 1'000'000) {
                std::cerr << usage << '\n';
                return 2;
            }
            panes = static_cast<int>(value);
        } else if (arg == "--out" && i + 1 < argc) {
            out = argv[++i];
        } else {
            std::cerr << usage << '\n';
            return arg == "--help" || arg == "-h" ? 0 : 2;
        }
    }
    if (out.empty())
        out = "/tmp/pane_field_" + std::string(opaque ? "opaque" : "blend") + "_" +
              std::to_string(panes) + ".gltf";
    return write(out, panes, opaque);
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& error) {
        std::cerr << "gltf_pane_field: " << error.what() << '\n';
        return 1;
    }
}
