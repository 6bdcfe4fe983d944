#include "scenes/gltf/gltf_support.h"

#include <array>
#include <charconv>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace monoplane::scenes::gltf {
namespace {

using nlohmann::json;

// Material extensions that refine shading the renderer approximates anyway (it has one albedo,
// one roughness and one specular value): ignoring them cannot misplace or garble geometry.
// (KHR_materials_pbrSpecularGlossiness is not among them: it replaces the base colour.)
constexpr std::array<std::string_view, 4> kIgnorableRequired = {
    "KHR_materials_unlit",
    "KHR_materials_emissive_strength",
    "KHR_materials_ior",
    "KHR_materials_specular",
};

// Why a known extension cannot be honoured, for the message.
std::string what_it_needs(std::string_view name) {
    if (name == "KHR_draco_mesh_compression" || name == "EXT_meshopt_compression") {
        return "compressed geometry this build cannot decode";
    }
    if (name == "KHR_mesh_quantization") return "quantized vertex attributes";
    if (name == "KHR_texture_transform") return "texture coordinate transforms";
    if (name == "KHR_texture_basisu" || name == "EXT_texture_webp") {
        return "an image format this build cannot decode";
    }
    return "an extension this loader does not know";
}

struct Version {
    int major = 0;
    int minor = 0;
};

// "2.0" -> {2, 0}; anything else (glTF wants MAJOR.MINOR) -> nothing.
bool parse_version(const std::string& text, Version& version) {
    const char* begin = text.data();
    const char* end = begin + text.size();
    auto [dot, error] = std::from_chars(begin, end, version.major);
    if (error != std::errc() || dot == end || *dot != '.') return false;
    auto [rest, minor_error] = std::from_chars(dot + 1, end, version.minor);
    return minor_error == std::errc() && rest == end;
}

// glTF 1.0 keeps its meshes, nodes... in objects keyed by name; 2.0 in arrays.
bool looks_like_gltf_1(const json& root) {
    for (const char* name : {"meshes", "nodes", "accessors", "buffers", "scenes"}) {
        const auto found = root.find(name);
        if (found != root.end() && found->is_object()) return true;
    }
    return false;
}

// Required extensions whose absence changes only shading details the renderer does not have.
bool is_ignorable_required_extension(std::string_view name) {
    for (const std::string_view known : kIgnorableRequired) {
        if (known == name) return true;
    }
    return false;
}

}  // namespace

Result<void> check_supported(const json& root) {
    if (!root.is_object()) return Ok{};  // check_json_schema() says what is wrong
    const auto asset = root.find("asset");
    const json* version = nullptr;
    if (asset != root.end() && asset->is_object()) {
        const auto found = asset->find("version");
        if (found != asset->end() && found->is_string()) version = &*found;
    }
    if (version == nullptr) {
        if (looks_like_gltf_1(root)) {
            return Error{
                "glTF 1.0 is not supported (no asset.version, and meshes or nodes are "
                "objects, not arrays): convert the file to glTF 2.0"};
        }
        return Error{"asset.version is missing (a glTF 2.0 file says \"2.0\")"};
    }
    const std::string text = version->get<std::string>();
    Version parsed;
    if (!parse_version(text, parsed)) {
        return Error{"asset.version \"" + text + "\" is not a MAJOR.MINOR version"};
    }
    if (parsed.major != 2) {
        return Error{"glTF " + text + " is not supported (asset.version is \"" + text +
                     "\"): only glTF 2.0 is" +
                     (parsed.major < 2 ? std::string(", convert the file to glTF 2.0") : "")};
    }
    const auto min_version = asset->find("minVersion");
    if (min_version != asset->end() && min_version->is_string()) {
        const std::string min_text = min_version->get<std::string>();
        Version minimum;
        if (parse_version(min_text, minimum) && (minimum.major != 2 || minimum.minor > 0)) {
            return Error{"the file needs glTF " + min_text +
                         " (asset.minVersion), this loader reads glTF 2.0"};
        }
    }
    const auto required = root.find("extensionsRequired");
    if (required != root.end() && required->is_array()) {
        for (const json& extension : *required) {
            if (!extension.is_string()) continue;  // check_json_schema() reports it
            const std::string name = extension.get<std::string>();
            if (is_ignorable_required_extension(name)) continue;
            return Error{"the file requires the extension " + name + " (" + what_it_needs(name) +
                         "), which this loader does not support"};
        }
    }
    return Ok{};
}

}  // namespace monoplane::scenes::gltf
