// Small glTF files written by the tests themselves: a JSON document built with nlohmann-json and
// one binary buffer, saved as .gltf (buffer embedded as base64, or beside it as a .bin) or .glb.
// Accessors are added from plain vectors so each test states its geometry by hand.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "scenes/gltf/load_gltf.h"

namespace monoplane::scenes::testing {

// Options for tests: no progress line and no warning line on stderr.
inline GltfLoadOptions quiet() {
    GltfLoadOptions options;
    options.progress = false;
    options.print_warnings = false;
    return options;
}

inline constexpr int kByte = 5120;
inline constexpr int kUnsignedByte = 5121;
inline constexpr int kShort = 5122;
inline constexpr int kUnsignedShort = 5123;
inline constexpr int kUnsignedInt = 5125;
inline constexpr int kFloat = 5126;

inline std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string text;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t a = bytes[i];
        const std::uint32_t b = i + 1 < bytes.size() ? bytes[i + 1] : 0;
        const std::uint32_t c = i + 2 < bytes.size() ? bytes[i + 2] : 0;
        const std::uint32_t triple = (a << 16) | (b << 8) | c;
        text += digits[(triple >> 18) & 63];
        text += digits[(triple >> 12) & 63];
        text += i + 1 < bytes.size() ? digits[(triple >> 6) & 63] : '=';
        text += i + 2 < bytes.size() ? digits[triple & 63] : '=';
    }
    return text;
}

class TestGltf {
  public:
    nlohmann::json json;
    std::vector<unsigned char> bin;

    TestGltf() {
        json["asset"] = {{"version", "2.0"}};
        json["buffers"] = nlohmann::json::array();
        json["bufferViews"] = nlohmann::json::array();
        json["accessors"] = nlohmann::json::array();
        json["meshes"] = nlohmann::json::array();
        json["nodes"] = nlohmann::json::array();
    }

    // Appends raw bytes as a new buffer view (4-byte aligned); returns its index.
    int add_view(const void* data, std::size_t bytes, int stride = 0) {
        while (bin.size() % 4 != 0) bin.push_back(0);
        nlohmann::json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
        if (stride != 0) view["byteStride"] = stride;
        const auto* p = static_cast<const unsigned char*>(data);
        bin.insert(bin.end(), p, p + bytes);
        json["bufferViews"].push_back(view);
        return static_cast<int>(json["bufferViews"].size()) - 1;
    }

    // An accessor over a new view holding `values`; returns the accessor's index.
    template <class T>
    int add_accessor(const std::vector<T>& values, int component_type, const std::string& type,
                     std::size_t count, bool normalized = false) {
        const int view = add_view(values.data(), values.size() * sizeof(T));
        nlohmann::json accessor = {{"bufferView", view},
                                   {"componentType", component_type},
                                   {"count", count},
                                   {"type", type}};
        if (normalized) accessor["normalized"] = true;
        json["accessors"].push_back(accessor);
        return static_cast<int>(json["accessors"].size()) - 1;
    }

    int add_positions(const std::vector<glm::vec3>& points) {
        std::vector<float> flat;
        for (const glm::vec3& p : points) flat.insert(flat.end(), {p.x, p.y, p.z});
        return add_accessor(flat, kFloat, "VEC3", points.size());
    }
    int add_vec2(const std::vector<glm::vec2>& points) {
        std::vector<float> flat;
        for (const glm::vec2& p : points) flat.insert(flat.end(), {p.x, p.y});
        return add_accessor(flat, kFloat, "VEC2", points.size());
    }
    int add_indices(const std::vector<std::uint32_t>& indices, int component_type = kUnsignedInt) {
        if (component_type == kUnsignedByte) {
            std::vector<std::uint8_t> narrow(indices.begin(), indices.end());
            return add_accessor(narrow, component_type, "SCALAR", indices.size());
        }
        if (component_type == kUnsignedShort) {
            std::vector<std::uint16_t> narrow(indices.begin(), indices.end());
            return add_accessor(narrow, component_type, "SCALAR", indices.size());
        }
        return add_accessor(indices, component_type, "SCALAR", indices.size());
    }

    // A mesh of one primitive; returns the mesh's index.
    int add_mesh(const nlohmann::json& attributes, int indices = -1, int mode = 4,
                 int material = -1, const std::string& name = "") {
        nlohmann::json primitive = {{"attributes", attributes}, {"mode", mode}};
        if (indices >= 0) primitive["indices"] = indices;
        if (material >= 0) primitive["material"] = material;
        nlohmann::json mesh = {{"primitives", nlohmann::json::array({primitive})}};
        if (!name.empty()) mesh["name"] = name;
        json["meshes"].push_back(mesh);
        return static_cast<int>(json["meshes"].size()) - 1;
    }

    // A node (with the given extra properties) and, if root, a place in scene 0.
    int add_node(nlohmann::json node, bool root = true) {
        json["nodes"].push_back(node);
        const int index = static_cast<int>(json["nodes"].size()) - 1;
        if (root) {
            if (!json.contains("scenes")) json["scenes"] = {{{"nodes", nlohmann::json::array()}}};
            json["scenes"][0]["nodes"].push_back(index);
        }
        return index;
    }

    // Buffer 0 as a base64 data: URI in a .gltf.
    void write_gltf(const std::filesystem::path& path) {
        nlohmann::json copy = json;
        copy["buffers"] = {{{"byteLength", bin.size()},
                            {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
        if (bin.empty()) copy.erase("buffers");
        write_text(path, copy.dump());
    }

    // Buffer 0 beside the .gltf as bin_name.
    void write_gltf_with_bin(const std::filesystem::path& path, const std::string& bin_name) {
        nlohmann::json copy = json;
        copy["buffers"] = {{{"byteLength", bin.size()}, {"uri", bin_name}}};
        write_text(path, copy.dump());
        std::ofstream out(path.parent_path() / bin_name, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bin.data()),
                  static_cast<std::streamsize>(bin.size()));
    }

    // A .glb with buffer 0 in its BIN chunk.
    void write_glb(const std::filesystem::path& path) {
        nlohmann::json copy = json;
        if (!bin.empty()) copy["buffers"] = {{{"byteLength", bin.size()}}};
        std::string text = copy.dump();
        while (text.size() % 4 != 0) text += ' ';
        std::vector<unsigned char> body = bin;
        while (body.size() % 4 != 0) body.push_back(0);
        std::vector<unsigned char> out;
        auto u32 = [&](std::uint32_t v) {
            for (int i = 0; i < 4; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
        };
        const std::size_t length = 12 + 8 + text.size() + (body.empty() ? 0 : 8 + body.size());
        out.insert(out.end(), {'g', 'l', 'T', 'F'});
        u32(2);
        u32(static_cast<std::uint32_t>(length));
        u32(static_cast<std::uint32_t>(text.size()));
        u32(0x4E4F534A);
        out.insert(out.end(), text.begin(), text.end());
        if (!body.empty()) {
            u32(static_cast<std::uint32_t>(body.size()));
            u32(0x004E4942);
            out.insert(out.end(), body.begin(), body.end());
        }
        std::ofstream file(path, std::ios::binary);
        file.write(reinterpret_cast<const char*>(out.data()),
                   static_cast<std::streamsize>(out.size()));
    }

    static void write_text(const std::filesystem::path& path, const std::string& text) {
        std::ofstream out(path, std::ios::binary);
        out << text;
    }
};

// A fresh directory per test and process under the system's temporary directory (ctest runs
// tests in parallel, and other build trees may run the same tests at once), removed when the
// process exits.
inline std::filesystem::path test_directory(const std::string& name) {
    static std::vector<std::filesystem::path> created;
    static const bool cleanup_registered = [] {
        std::atexit([] {
            std::error_code ignored;
            for (const std::filesystem::path& dir : created)
                std::filesystem::remove_all(dir, ignored);
        });
        return true;
    }();
    static_cast<void>(cleanup_registered);
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("monoplane_gltf_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    created.push_back(dir);
    return dir;
}

}  // namespace monoplane::scenes::testing
