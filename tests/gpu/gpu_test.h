// GPU test fixture: one Vulkan context per test with the validation layer on; any validation
// message fails the test.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

#include "renderer/vk/context.h"

namespace monoplane::testing {

inline std::unique_ptr<vk_core::Context> make_validated_context() {
    vk_core::ContextOptions options;
    options.validation = true;
    if (const char* device = std::getenv("MONOPLANE_TEST_DEVICE")) options.device_selector = device;
    auto ctx = vk_core::Context::create(options);
    if (!ctx) {
        ADD_FAILURE() << ctx.error().message;
        return nullptr;
    }
    return std::move(ctx).value();
}

class GpuTest : public ::testing::Test {
  protected:
    void SetUp() override {
        ctx_ = make_validated_context();
        ASSERT_NE(ctx_, nullptr);
    }
    void TearDown() override {
        if (!ctx_) return;
        ctx_->device().waitIdle();
        EXPECT_EQ(ctx_->validation_messages().count(), 0u) << [this] {
            std::string text;
            for (const auto& m : ctx_->validation_messages().first_messages()) text += m + "\n";
            return text;
        }();
    }
    vk_core::Context& ctx() { return *ctx_; }

  private:
    std::unique_ptr<vk_core::Context> ctx_;
};

}  // namespace monoplane::testing
