#include "scenes/gltf/texture_decode.h"

#include <limits>
#include <memory>
#include <span>
#include <string>
#include <system_error>

#include "scenes/gltf/buffer_sources.h"

// A private copy of stb_image (every function static): no symbol can collide with the
// STB_IMAGE_IMPLEMENTATION of another target, and sanitizer builds instrument the decoder.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#define STBI_MAX_DIMENSIONS 32768
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace monoplane::scenes::gltf {
namespace {

struct FreeImage {
    void operator()(stbi_uc* pixels) const { stbi_image_free(pixels); }
};

TextureWrap wrap_of(int gltf_wrap) {
    switch (gltf_wrap) {
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
            return TextureWrap::ClampToEdge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
            return TextureWrap::MirroredRepeat;
        default:
            return TextureWrap::Repeat;  // glTF's default, and what 10497 means
    }
}

// The encoded bytes of an image: from its buffer view (checked here: tinygltf does not) or
// from the file or data: URI tinygltf read.
Result<std::span<const unsigned char>> encoded_bytes(const GltfDocument& document,
                                                     const tinygltf::Image& image) {
    const tinygltf::Model& model = document.model;
    if (image.bufferView >= 0) {
        if (static_cast<std::size_t>(image.bufferView) >= model.bufferViews.size()) {
            return Error{"buffer view " + std::to_string(image.bufferView) + " does not exist"};
        }
        const tinygltf::BufferView& view =
            model.bufferViews[static_cast<std::size_t>(image.bufferView)];
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
            return Error{"buffer view " + std::to_string(image.bufferView) + " has no buffer"};
        }
        const std::vector<unsigned char>& data =
            model.buffers[static_cast<std::size_t>(view.buffer)].data;
        if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
            return Error{"buffer view " + std::to_string(image.bufferView) +
                         " lies outside its buffer (" + std::to_string(data.size()) + " bytes)"};
        }
        return std::span<const unsigned char>(data.data() + view.byteOffset, view.byteLength);
    }
    if (!image.image.empty()) return std::span<const unsigned char>(image.image);
    if (is_base64_data_uri(image.uri)) return Error{"its data: URI holds no bytes"};
    const std::optional<std::string> relative = uri_to_relative_path(image.uri);
    if (!relative) return Error{"its uri is not a path relative to the glTF file"};
    std::error_code error;
    if (!std::filesystem::is_regular_file(document.base_directory / *relative, error)) {
        return Error{"file not found in " + (document.base_directory.empty()
                                                 ? std::string("the current directory")
                                                 : document.base_directory.string())};
    }
    return Error{"file is empty or cannot be read"};
}

std::string describe(const tinygltf::Model& model, int texture, int image) {
    std::string text = "texture " + std::to_string(texture);
    if (image < 0) return text;
    const tinygltf::Image& source = model.images[static_cast<std::size_t>(image)];
    const std::string& label = !source.name.empty() ? source.name : source.uri;
    text += " (image " + std::to_string(image);
    if (!label.empty() && label.rfind("data:", 0) != 0) text += " '" + label + "'";
    return text + ")";
}

}  // namespace

Result<SceneTexture> decode_texture(const GltfDocument& document, int texture,
                                    std::uint64_t max_texels) {
    const tinygltf::Model& model = document.model;
    if (texture < 0 || static_cast<std::size_t>(texture) >= model.textures.size()) {
        return Error{"texture " + std::to_string(texture) + " does not exist"};
    }
    const tinygltf::Texture& source = model.textures[static_cast<std::size_t>(texture)];
    const int image_index = source.source;
    const std::string name = describe(model, texture, image_index);
    if (image_index < 0 || static_cast<std::size_t>(image_index) >= model.images.size()) {
        return Error{name + " has no image glTF can decode (source)"};
    }
    const tinygltf::Image& image = model.images[static_cast<std::size_t>(image_index)];
    Result<std::span<const unsigned char>> bytes = encoded_bytes(document, image);
    if (!bytes) return Error{name + ": " + bytes.error().message};
    if (bytes->size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
        return Error{name + " is larger than 2 GiB"};
    }
    const int size = static_cast<int>(bytes->size());
    int width = 0;
    int height = 0;
    int channels = 0;
    if (stbi_info_from_memory(bytes->data(), size, &width, &height, &channels) == 0) {
        return Error{name + " is not a PNG or JPEG image that can be decoded (" +
                     stbi_failure_reason() + ")"};
    }
    const std::uint64_t texels =
        static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
    if (texels > max_texels) {
        return Error{name + " has " + std::to_string(width) + " x " + std::to_string(height) +
                     " texels, more than the limit of " + std::to_string(max_texels)};
    }
    const std::unique_ptr<stbi_uc, FreeImage> pixels(
        stbi_load_from_memory(bytes->data(), size, &width, &height, &channels, 4));
    if (!pixels) {
        return Error{name + " cannot be decoded (" + std::string(stbi_failure_reason()) + ")"};
    }
    SceneTexture result;
    result.name = image.name.empty() && image.uri.rfind("data:", 0) != 0 ? image.uri : image.name;
    result.width = static_cast<std::uint32_t>(width);
    result.height = static_cast<std::uint32_t>(height);
    result.rgba8_srgb.assign(pixels.get(), pixels.get() + texels * 4);
    if (source.sampler >= 0 && static_cast<std::size_t>(source.sampler) < model.samplers.size()) {
        const tinygltf::Sampler& sampler = model.samplers[static_cast<std::size_t>(source.sampler)];
        result.wrap_u = wrap_of(sampler.wrapS);
        result.wrap_v = wrap_of(sampler.wrapT);
    }
    return result;
}

}  // namespace monoplane::scenes::gltf
