#include "renderer/passes/shared/scene_textures.h"

#include <algorithm>
#include <bit>
#include <string>

#include <glm/vec2.hpp>

#include "common/result.h"
#include "renderer/executor/image_layouts.h"
#include "renderer/passes/shared/scene_texture_constants.h"
#include "scenes/texture_mips.h"

namespace monoplane::passes {
namespace {

static_assert(MONOPLANE_TEXTURE_ARRAYS == scenes::kTextureArrayCount &&
                  MONOPLANE_TEXTURE_SMALLEST_SIDE == scenes::kTextureArraySmallestSide,
              "scene_texture_constants.h and scenes/texture_arrays.h describe the same arrays");
static_assert(MONOPLANE_TEXTURE_ARRAYS == 7, "scene_textures.glsl's switch names seven arrays");

constexpr vk::Format kTextureFormat = vk::Format::eR8G8B8A8Srgb;

std::uint32_t wrap_word(scenes::TextureWrap wrap) {
    switch (wrap) {
        case scenes::TextureWrap::ClampToEdge:
            return MONOPLANE_WRAP_CLAMP;
        case scenes::TextureWrap::MirroredRepeat:
            return MONOPLANE_WRAP_MIRROR;
        case scenes::TextureWrap::Repeat:
            break;
    }
    return MONOPLANE_WRAP_REPEAT;
}

// A scene without texture coordinates still binds a buffer (of one coordinate nobody reads).
template <class T>
vk_core::Buffer storage_buffer(const vk_core::Context& ctx, std::vector<T> items) {
    if (items.empty()) items.resize(1);
    return vk_core::make_device_buffer(ctx, std::span<const T>(items),
                                       vk::BufferUsageFlagBits::eStorageBuffer);
}

// Per chunk: its texture and its alpha cut-off's bits (scene_textures.glsl's chunk_surface).
std::vector<glm::ivec2> chunk_surface_words(const scenes::Scene& scene) {
    std::vector<glm::ivec2> words;
    words.reserve(scene.chunks.size());
    for (const scenes::Chunk& chunk : scene.chunks) {
        words.emplace_back(chunk.texture, std::bit_cast<std::int32_t>(chunk.alpha_cutoff));
    }
    return words;
}

std::vector<glm::uvec4> slot_words(const scenes::Scene& scene,
                                   const scenes::TextureArrayLayout& layout) {
    std::vector<glm::uvec4> words;
    for (std::size_t t = 0; t < scene.textures.size(); ++t) {
        const scenes::SceneTexture& texture = scene.textures[t];
        words.emplace_back(layout.slots[t].array, layout.slots[t].layer, wrap_word(texture.wrap_u),
                           wrap_word(texture.wrap_v));
    }
    return words;
}

void check_device_limits(const vk_core::Context& ctx, const scenes::Scene& scene,
                         const scenes::TextureArrayLayout& layout) {
    if (scene.textures.empty()) return;
    const vk_core::DeviceCapabilities& caps = ctx.capabilities();
    const std::string device = "device '" + ctx.device_info().name + "'";
    if (!caps.draw_indirect_first_instance) {
        throw UserError(device +
                        " lacks drawIndirectFirstInstance, by which textured chunks "
                        "find their texture; choose another with --device");
    }
    for (std::uint32_t a = 0; a < scenes::kTextureArrayCount; ++a) {
        if (layout.layers[a] == 0) continue;
        const std::uint32_t side = scenes::TextureArrayLayout::side(a);
        if (side > caps.max_image_dimension_2d) {
            throw UserError(device + " allows images of " +
                            std::to_string(caps.max_image_dimension_2d) +
                            " texels a side; scene '" + scene.name + "' has textures that need " +
                            std::to_string(side));
        }
        if (layout.layers[a] > caps.max_image_array_layers) {
            throw UserError(scene.name + " has " + std::to_string(layout.layers[a]) +
                            " textures of side " + std::to_string(side) + ", more than the " +
                            std::to_string(caps.max_image_array_layers) + " layers " + device +
                            " allows in one array");
        }
    }
}

// Copies one texture's mip chain into its layer of `array` (in eTransferDstOptimal).
std::uint64_t upload_layer(const vk_core::Context& ctx, const vk_core::Image& array,
                           const scenes::SceneTexture& texture, std::uint32_t side,
                           std::uint32_t layer) {
    const std::vector<scenes::MipLevel> chain =
        scenes::make_mip_chain(scenes::texture_as_layer(texture, side));
    std::uint64_t bytes = 0;
    for (const scenes::MipLevel& level : chain) bytes += level.rgba8_srgb.size();
    const vk_core::Buffer staging(ctx, bytes, vk::BufferUsageFlagBits::eTransferSrc,
                                  vk_core::MemoryUse::kHostVisible);
    std::vector<vk::BufferImageCopy> copies;
    vk::DeviceSize offset = 0;
    for (std::uint32_t level = 0; level < chain.size(); ++level) {
        const scenes::MipLevel& mip = chain[level];
        staging.write(mip.rgba8_srgb.data(), mip.rgba8_srgb.size(), offset);
        copies.emplace_back(
            offset, 0, 0,
            vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, level, layer, 1),
            vk::Offset3D(0, 0, 0), vk::Extent3D(mip.width, mip.height, 1));
        offset += mip.rgba8_srgb.size();
    }
    ctx.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
        cmd.copyBufferToImage(staging.handle(), array.handle(),
                              executor::layout_for(graph::Use::kTransferDst), copies);
    });
    return bytes;
}

}  // namespace

SceneTextures::SceneTextures(const vk_core::Context& ctx, const scenes::Scene& scene)
    : texcoords_(storage_buffer(ctx, scene.texcoords)),
      chunk_textures_(storage_buffer(ctx, chunk_surface_words(scene))) {
    const scenes::TextureArrayLayout layout = scenes::layout_texture_arrays(scene.textures);
    check_device_limits(ctx, scene, layout);
    texture_slots_ = storage_buffer(ctx, slot_words(scene, layout));
    upload_arrays(ctx, scene, layout);

    using Stage = vk::ShaderStageFlagBits;
    const std::array bindings = {
        vk::DescriptorSetLayoutBinding(0, vk::DescriptorType::eStorageBuffer, 1, Stage::eVertex),
        vk::DescriptorSetLayoutBinding(1, vk::DescriptorType::eStorageBuffer, 1, Stage::eVertex),
        vk::DescriptorSetLayoutBinding(2, vk::DescriptorType::eStorageBuffer, 1, Stage::eVertex),
        vk::DescriptorSetLayoutBinding(3, vk::DescriptorType::eSampledImage,
                                       scenes::kTextureArrayCount, Stage::eFragment),
        vk::DescriptorSetLayoutBinding(4, vk::DescriptorType::eSampler, MONOPLANE_WRAP_SAMPLERS,
                                       Stage::eFragment),
    };
    layout_ = vk::raii::DescriptorSetLayout(ctx.device(),
                                            vk::DescriptorSetLayoutCreateInfo({}, bindings));
    const float anisotropy = std::min(8.0f, ctx.capabilities().max_sampler_anisotropy);
    for (std::uint32_t bits = 0; bits < MONOPLANE_WRAP_SAMPLERS; ++bits) {
        auto mode = [&](std::uint32_t clamp_bit) {
            return (bits & clamp_bit) != 0 ? vk::SamplerAddressMode::eClampToEdge
                                           : vk::SamplerAddressMode::eRepeat;
        };
        samplers_.emplace_back(
            ctx.device(),
            vk::SamplerCreateInfo({}, vk::Filter::eLinear, vk::Filter::eLinear,
                                  vk::SamplerMipmapMode::eLinear, mode(MONOPLANE_SAMPLER_CLAMP_U),
                                  mode(MONOPLANE_SAMPLER_CLAMP_V), vk::SamplerAddressMode::eRepeat,
                                  0.0f, anisotropy > 1.0f, anisotropy, false, vk::CompareOp::eNever,
                                  0.0f, VK_LOD_CLAMP_NONE));
    }
    write_set(ctx);
}

void SceneTextures::upload_arrays(const vk_core::Context& ctx, const scenes::Scene& scene,
                                  const scenes::TextureArrayLayout& layout) {
    for (std::uint32_t a = 0; a < scenes::kTextureArrayCount; ++a) {
        const bool used = layout.layers[a] > 0;
        const std::uint32_t side = used ? scenes::TextureArrayLayout::side(a) : 1;
        vk_core::ImageDesc desc{
            {side, side},
            kTextureFormat,
            vk::ImageUsageFlagBits::eTransferDst | vk::ImageUsageFlagBits::eSampled,
            used ? layout.layers[a] : 1};
        desc.mip_levels = scenes::mip_level_count(side, side);
        desc.array_view = true;
        const vk_core::Image& array = arrays_.emplace_back(ctx, desc);
        ctx.submit_and_wait(
            [&](const vk::raii::CommandBuffer& cmd) { vk_core::begin_upload(cmd, array); });
        if (used) {
            for (std::size_t t = 0; t < scene.textures.size(); ++t) {
                if (layout.slots[t].array != a) continue;
                image_bytes_ +=
                    upload_layer(ctx, array, scene.textures[t], side, layout.slots[t].layer);
            }
        } else {
            const scenes::SceneTexture white{"unused", 1, 1, {255, 255, 255, 255}};
            image_bytes_ += upload_layer(ctx, array, white, 1, 0);
        }
        ctx.submit_and_wait(
            [&](const vk::raii::CommandBuffer& cmd) { vk_core::end_upload(cmd, array); });
    }
}

void SceneTextures::write_set(const vk_core::Context& ctx) {
    const std::array sizes = {
        vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, 3),
        vk::DescriptorPoolSize(vk::DescriptorType::eSampledImage, scenes::kTextureArrayCount),
        vk::DescriptorPoolSize(vk::DescriptorType::eSampler, MONOPLANE_WRAP_SAMPLERS)};
    set_ = vk_core::DescriptorSet(ctx, *layout_, sizes);
    const std::array buffers = {
        vk::DescriptorBufferInfo(texcoords_.handle(), 0, VK_WHOLE_SIZE),
        vk::DescriptorBufferInfo(chunk_textures_.handle(), 0, VK_WHOLE_SIZE),
        vk::DescriptorBufferInfo(texture_slots_.handle(), 0, VK_WHOLE_SIZE)};
    std::vector<vk::DescriptorImageInfo> images;
    for (const vk_core::Image& array : arrays_) {
        images.emplace_back(nullptr, array.view(),
                            executor::layout_for(graph::Use::kSampledFragment));
    }
    std::vector<vk::DescriptorImageInfo> samplers;
    for (const vk::raii::Sampler& sampler : samplers_) samplers.emplace_back(*sampler);
    std::vector<vk::WriteDescriptorSet> writes;
    for (std::uint32_t b = 0; b < buffers.size(); ++b) {
        writes.emplace_back(*set_, b, 0, 1, vk::DescriptorType::eStorageBuffer, nullptr,
                            &buffers[b]);
    }
    writes.emplace_back(*set_, 3, 0, static_cast<std::uint32_t>(images.size()),
                        vk::DescriptorType::eSampledImage, images.data());
    writes.emplace_back(*set_, 4, 0, static_cast<std::uint32_t>(samplers.size()),
                        vk::DescriptorType::eSampler, samplers.data());
    ctx.device().updateDescriptorSets(writes, {});
}

}  // namespace monoplane::passes
