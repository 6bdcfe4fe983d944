#include "scenes/gltf/gltf_document.h"

#include <algorithm>
#include <exception>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scenes/gltf/buffer_sources.h"
#include "scenes/gltf/file_bytes.h"
#include "scenes/gltf/glb_container.h"
#include "scenes/gltf/gltf_support.h"
#include "scenes/gltf/json_schema.h"

namespace monoplane::scenes::gltf {
namespace {

// tinygltf's image callback: keep the encoded bytes, decode later (and only what is used).
bool keep_encoded_image(tinygltf::Image* image, int /*image_index*/, std::string* /*error*/,
                        std::string* /*warning*/, int /*width*/, int /*height*/,
                        const unsigned char* bytes, int size, void* /*user_data*/) {
    // A buffer-view image's bytes are sliced from its checked buffer view when it is decoded:
    // tinygltf hands them over without checking that the view lies inside its buffer.
    if (image->bufferView >= 0 || bytes == nullptr || size <= 0) return true;
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// tinygltf's file access, through read_file_bytes(), and only inside the file's directory:
// tinygltf would also look in the working directory ("./name") for what it does not find there.
struct FileAccess {
    std::string base_directory;
    std::vector<std::filesystem::path>* files_read;  // GltfDocument::files_read
};

bool file_exists(const std::string& path, void* user_data) {
    const auto* access = static_cast<const FileAccess*>(user_data);
    if (!access->base_directory.empty() && path.rfind("./", 0) == 0) return false;
    std::error_code error;
    return std::filesystem::is_regular_file(path, error);
}

std::string expand_path(const std::string& path, void* /*user_data*/) {
    return path;
}

bool read_whole_file(std::vector<unsigned char>* out, std::string* error, const std::string& path,
                     void* user_data) {
    Result<std::vector<unsigned char>> bytes = read_file_bytes(path);
    if (!bytes) {
        *error = bytes.error().message;
        return false;
    }
    *out = std::move(bytes).value();
    auto& files_read = *static_cast<const FileAccess*>(user_data)->files_read;
    const std::filesystem::path read = std::filesystem::path(path).lexically_normal();
    if (std::find(files_read.begin(), files_read.end(), read) == files_read.end()) {
        files_read.push_back(read);
    }
    return true;
}

bool refuse_write(std::string* error, const std::string& /*path*/,
                  const std::vector<unsigned char>& /*contents*/, void* /*user_data*/) {
    *error = "the glTF loader writes no files";
    return false;
}

// tinygltf's errors are lines ending in newlines and may quote a whole data: URI.
std::string first_line(const std::string& text) {
    constexpr std::size_t kLongest = 200;
    std::string line = text.substr(0, text.find('\n'));
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (line.size() > kLongest) line = line.substr(0, kLongest) + "...";
    return line.empty() ? "tinygltf could not read it" : line;
}

// nlohmann's messages start with "[json.exception.parse_error.101] parse error at ...".
std::string without_exception_tag(const std::string& message) {
    const std::size_t tag_end = message.find("] ");
    return tag_end == std::string::npos ? message : message.substr(tag_end + 2);
}

Result<void> check_json(std::string_view text, const std::filesystem::path& base_directory,
                        bool glb, std::size_t bin_size) {
    nlohmann::json root;
    try {
        root = nlohmann::json::parse(text.begin(), text.end());
    } catch (const nlohmann::json::exception& error) {
        return Error{
            std::string(glb ? "has a JSON chunk that is not valid JSON: " : "is not valid JSON: ") +
            without_exception_tag(error.what())};
    }
    MONOPLANE_TRY(check_supported(root));
    MONOPLANE_TRY(check_json_schema(root));
    return check_buffer_sources(root, base_directory, glb, bin_size);
}

}  // namespace

Result<GltfDocument> read_gltf_document(const std::filesystem::path& file) {
    GltfDocument document;
    document.base_directory = file.parent_path();
    std::vector<unsigned char> bytes;
    {
        Result<std::vector<unsigned char>> read = read_file_bytes(file);
        MONOPLANE_TRY(read);
        bytes = std::move(read).value();
    }
    if (bytes.empty()) return Error{"is empty"};
    document.files_read.push_back(file.lexically_normal());
    const std::span<const unsigned char> all(bytes);
    const bool glb = is_glb(all);
    std::string_view json_text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    std::size_t bin_size = 0;
    if (glb) {
        Result<GlbChunks> chunks = split_glb(all);
        MONOPLANE_TRY(chunks);
        json_text = chunks->json;
        bin_size = chunks->bin.size();
    }
    MONOPLANE_TRY(check_json(json_text, document.base_directory, glb, bin_size));

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&keep_encoded_image, nullptr);
    FileAccess access{document.base_directory.string(), &document.files_read};
    loader.SetFsCallbacks({&file_exists, &expand_path, &read_whole_file, &refuse_write, &access});
    std::string error;
    std::string warning;
    bool loaded = false;
    try {
        const std::string base = document.base_directory.string();
        const auto size = static_cast<unsigned int>(bytes.size());  // <= kMaxFileBytes
        loaded = glb ? loader.LoadBinaryFromMemory(&document.model, &error, &warning, bytes.data(),
                                                   size, base)
                     : loader.LoadASCIIFromString(&document.model, &error, &warning,
                                                  json_text.data(), size, base);
    } catch (const std::exception& exception) {
        return Error{std::string("cannot be read by tinygltf: ") + exception.what()};
    }
    if (!loaded) return Error{"cannot be read by tinygltf: " + first_line(error)};
    return document;
}

}  // namespace monoplane::scenes::gltf
