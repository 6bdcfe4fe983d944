#include "renderer/vk/descriptor_set.h"

#include <utility>
#include <vector>

namespace monoplane::vk_core {

DescriptorSet::DescriptorSet(const Context& ctx, vk::DescriptorSetLayout layout,
                             std::span<const vk::DescriptorPoolSize> sizes)
    : pool_(ctx.device(),
            vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 1,
                                         static_cast<std::uint32_t>(sizes.size()), sizes.data())),
      set_(std::move(vk::raii::DescriptorSets(ctx.device(),
                                              vk::DescriptorSetAllocateInfo(*pool_, layout))[0])) {}

void write_sampled_images(const Context& ctx, vk::DescriptorSet set,
                          std::span<const vk::DescriptorImageInfo> images,
                          std::uint32_t first_binding) {
    std::vector<vk::WriteDescriptorSet> writes;
    for (std::size_t i = 0; i < images.size(); ++i) {
        writes.emplace_back(set, first_binding + static_cast<std::uint32_t>(i), 0, 1,
                            vk::DescriptorType::eCombinedImageSampler, &images[i]);
    }
    ctx.device().updateDescriptorSets(writes, {});
}

}  // namespace monoplane::vk_core
