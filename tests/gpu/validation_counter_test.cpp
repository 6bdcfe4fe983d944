// The message counter must see a real validation error, or "zero messages" would prove nothing.
#include <gtest/gtest.h>

#include "tests/gpu/gpu_test.h"

namespace monoplane {
namespace {

TEST(ValidationCounter, CountsAnInvalidCall) {
    auto ctx = testing::make_validated_context();
    ASSERT_NE(ctx, nullptr);
    ASSERT_EQ(ctx->validation_messages().count(), 0u);
    // VUID-VkBufferCreateInfo-usage-requiredbitmask: usage must not be 0.
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = 256;
    info.usage = 0;
    VkBuffer buffer = VK_NULL_HANDLE;
    const VkDevice device = *ctx->device();
    if (ctx->device().getDispatcher()->vkCreateBuffer(device, &info, nullptr, &buffer) ==
        VK_SUCCESS) {
        ctx->device().getDispatcher()->vkDestroyBuffer(device, buffer, nullptr);
    }
    EXPECT_GE(ctx->validation_messages().count(), 1u);
    ASSERT_FALSE(ctx->validation_messages().first_messages().empty());
    EXPECT_NE(ctx->validation_messages().first_messages().front().find("usage"), std::string::npos);
}

}  // namespace
}  // namespace monoplane
