// An imported scene's base-colour textures on the GPU, and what the forward pass reads them by
// (its descriptor set 2, renderer/passes/shared/scene_textures.glsl):
//   binding 0  the texture coordinates, parallel to the vertices (Scene::texcoords)
//   binding 1  per chunk, its texture (Chunk::texture) or -1, and its alpha cut-off
//   binding 2  per texture, where it lies: array, layer, wrap_u, wrap_v
//   binding 3  the texture arrays (scenes/texture_arrays.h), sRGB, mip-mapped
//   binding 4  four samplers, repeating or clamping to the edge per axis (trilinear, and
//              anisotropic where the device filters so); mirrored repeat is folded in the shader
//              and clamped, which reads the texels around a fold as a mirroring sampler does
// The vertex shader finds its chunk's texture through the draw's first instance (the culling
// pass's chunk index) and pulls its coordinate by gl_VertexIndex; the fragment shader samples.
// A scene without textures gets a set of the same form whose chunks all say -1 (nothing is read
// but the chunk words), so one pipeline serves every scene.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "renderer/vk/buffer.h"
#include "renderer/vk/descriptor_set.h"
#include "renderer/vk/image.h"
#include "scenes/scene.h"
#include "scenes/texture_arrays.h"

namespace monoplane::passes {

class SceneTextures {
  public:
    // Uploads the scene's textures (each resampled to its array's side, with a full mip chain)
    // and waits. Refuses (UserError) a textured scene on a device without
    // drawIndirectFirstInstance, or whose arrays exceed the device's image limits, naming the
    // limit.
    SceneTextures(const vk_core::Context& ctx, const scenes::Scene& scene);

    // The layout of set 2, for pipeline layouts of passes that draw scene chunks.
    vk::DescriptorSetLayout layout() const { return *layout_; }
    vk::DescriptorSet set() const { return *set_; }
    // Device memory the texture arrays take, in bytes (study run and render report it).
    std::uint64_t image_bytes() const { return image_bytes_; }

  private:
    void upload_arrays(const vk_core::Context& ctx, const scenes::Scene& scene,
                       const scenes::TextureArrayLayout& layout);
    void write_set(const vk_core::Context& ctx);

    vk::raii::DescriptorSetLayout layout_{nullptr};
    vk_core::Buffer texcoords_;
    vk_core::Buffer chunk_textures_;
    vk_core::Buffer texture_slots_;
    // One per scenes::TextureArrayLayout array; an unused array is a 1 x 1 white layer.
    std::vector<vk_core::Image> arrays_;
    std::vector<vk::raii::Sampler> samplers_;  // by MONOPLANE_SAMPLER_* bits
    vk_core::DescriptorSet set_;
    std::uint64_t image_bytes_ = 0;
};

}  // namespace monoplane::passes
