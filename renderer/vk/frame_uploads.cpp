#include "renderer/vk/frame_uploads.h"

#include <algorithm>
#include <cstring>

#include "common/programming_error.h"

namespace monoplane::vk_core {
namespace {

// vkCmdUpdateBuffer's limit per command (Vulkan spec: dataSize <= 65536).
constexpr vk::DeviceSize kMaxUpdate = 65536;

}  // namespace

void FrameUploads::stage(const Buffer& target, const void* data, vk::DeviceSize bytes,
                         vk::DeviceSize offset) {
    // A range of whole words inside the buffer.
    MONOPLANE_EXPECTS(bytes % 4 == 0 && offset % 4 == 0 && offset + bytes <= target.size());
    const auto* from = static_cast<const std::byte*>(data);
    for (vk::DeviceSize done = 0; done < bytes; done += kMaxUpdate) {
        const vk::DeviceSize size = std::min(kMaxUpdate, bytes - done);
        updates_.push_back(
            {target.handle(), offset + done, bytes_.size(), static_cast<std::size_t>(size)});
        bytes_.insert(bytes_.end(), from + done, from + done + size);
    }
}

void FrameUploads::record(const vk::raii::CommandBuffer& cmd) {
    if (updates_.empty()) return;
    using Stage = vk::PipelineStageFlagBits2;
    using Access = vk::AccessFlagBits2;
    // A later update of a range an earlier one wrote must wait for it (the later stage wins).
    const vk::MemoryBarrier2 in_order(Stage::eTransfer, Access::eTransferWrite, Stage::eTransfer,
                                      Access::eTransferWrite);
    for (std::size_t i = 0; i < updates_.size(); ++i) {
        const Update& u = updates_[i];
        const bool overlaps = std::any_of(
            updates_.begin(), updates_.begin() + static_cast<std::ptrdiff_t>(i),
            [&u](const Update& earlier) {
                return earlier.target == u.target && earlier.offset < u.offset + u.size &&
                       u.offset < earlier.offset + earlier.size;
            });
        if (overlaps) cmd.pipelineBarrier2(vk::DependencyInfo({}, in_order));
        // The raw call: Vulkan-Hpp's typed overload takes an ArrayProxy of one element type.
        cmd.getDispatcher()->vkCmdUpdateBuffer(*cmd, u.target, u.offset, u.size,
                                               bytes_.data() + u.first);
    }
    const vk::MemoryBarrier2 visible(
        Stage::eTransfer, Access::eTransferWrite, Stage::eAllCommands,
        Access::eUniformRead | Access::eShaderStorageRead | Access::eIndirectCommandRead);
    cmd.pipelineBarrier2(vk::DependencyInfo({}, visible));
    updates_.clear();
    bytes_.clear();
}

}  // namespace monoplane::vk_core
