// Measures glTF import on a large scene (issue 19 item 2): `gltf_big_scene write FILE.glb
// [TRIANGLES] [MESHES]` writes a rolling terrain of that many triangles (default 2 M) in that
// many meshes (default 10, one node each, no normals: the loader generates them), and
// `gltf_big_scene load FILE.glb` loads it with the progress line on and prints the time, the
// scene's size and the process's peak memory. Two commands so that the peak belongs to the load
// alone. Not a test (no test asserts a time); write to /tmp, not the tree.
#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "scenes/gltf/load_gltf.h"
#include "tests/unit/gltf_test_files.h"

namespace {

using monoplane::scenes::testing::TestGltf;

int write(const std::string& path, std::size_t triangles, std::size_t meshes) {
    const std::size_t per_mesh = (triangles + meshes - 1) / meshes;
    const auto side =
        static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(per_mesh) / 2.0)));
    TestGltf file;
    for (std::size_t m = 0; m < meshes; ++m) {
        std::vector<glm::vec3> positions;
        positions.reserve(std::size_t{side + 1} * (side + 1));
        for (std::uint32_t z = 0; z <= side; ++z) {
            for (std::uint32_t x = 0; x <= side; ++x) {
                const float fx = static_cast<float>(x) * 0.25f;
                const float fz = -static_cast<float>(z) * 0.25f;
                positions.emplace_back(fx, 0.4f * std::sin(0.3f * fx) * std::cos(0.2f * fz), fz);
            }
        }
        std::vector<std::uint32_t> indices;
        indices.reserve(std::size_t{6} * side * side);
        for (std::uint32_t z = 0; z < side; ++z) {
            for (std::uint32_t x = 0; x < side; ++x) {
                const std::uint32_t a = z * (side + 1) + x;
                const std::uint32_t c = a + side + 1;
                indices.insert(indices.end(), {a, a + 1, c + 1, a, c + 1, c});
            }
        }
        const int mesh =
            file.add_mesh({{"POSITION", file.add_positions(positions)}}, file.add_indices(indices),
                          4, -1, "tile" + std::to_string(m));
        const float offset = static_cast<float>(m) * 0.25f * static_cast<float>(side);
        file.add_node({{"mesh", mesh}, {"translation", {offset, 0.0f, 0.0f}}});
    }
    file.write_glb(path);
    std::cout << "wrote " << path << ": " << meshes << " meshes of " << 2u * side * side
              << " triangles\n";
    return 0;
}

int load(const std::string& path) {
    monoplane::scenes::GltfLoadOptions options;
    options.progress = true;
    monoplane::scenes::GltfLoadReport report;
    const auto scene = monoplane::scenes::load_gltf_scene(path, options, &report);
    if (!scene) {
        std::cerr << scene.error().message << '\n';
        return 1;
    }
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const double vertex_mb =
        static_cast<double>(scene->vertices.size() * sizeof(monoplane::scenes::Vertex)) / 1e6;
    const double index_mb = static_cast<double>(scene->indices.size() * 4) / 1e6;
    std::printf(
        "%s: %zu triangles, %zu vertices, %zu chunks in %.2f s; scene %.0f MB (vertices %.0f, "
        "indices %.0f); peak resident %.0f MB\n",
        path.c_str(), scene->triangle_count(), scene->vertices.size(), scene->chunks.size(),
        report.seconds, vertex_mb + index_mb, vertex_mb, index_mb,
        static_cast<double>(usage.ru_maxrss) / 1024.0);
    return 0;
}

int run(int argc, char** argv) {
    const std::string usage =
        "usage: gltf_big_scene write FILE.glb [TRIANGLES] [MESHES] | load FILE.glb";
    if (argc >= 3 && std::string(argv[1]) == "write") {
        const std::size_t triangles = argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 2'000'000;
        const std::size_t meshes = argc > 4 ? std::strtoull(argv[4], nullptr, 10) : 10;
        if (triangles == 0 || meshes == 0) {
            std::cerr << usage << '\n';
            return 2;
        }
        return write(argv[2], triangles, meshes);
    }
    if (argc == 3 && std::string(argv[1]) == "load") return load(argv[2]);
    std::cerr << usage << '\n';
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& error) {
        std::cerr << "gltf_big_scene: " << error.what() << '\n';
        return 1;
    }
}
