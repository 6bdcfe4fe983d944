#include "app/commands/validation_report.h"

#include <iostream>
#include <string>

#include "common/result.h"

namespace monoplane::app {
namespace {

// Prints the first messages; returns the count.
std::size_t print_messages(const vk_core::ValidationMessages& messages) {
    for (const auto& message : messages.first_messages()) std::cerr << message << "\n";
    return messages.count();
}

}  // namespace

void fail_on_validation_messages(const vk_core::Context& ctx, const GlobalOptions& global) {
    if (!global.validation || ctx.validation_messages().count() == 0) return;
    const std::size_t count = print_messages(ctx.validation_messages());
    throw UserError(std::to_string(count) + " Vulkan validation message(s)");
}

void fail_on_validation_messages(const vk_core::Context& ctx,
                                 const vk_core::ValidationMessages& openxr,
                                 const GlobalOptions& global) {
    if (!global.validation) return;
    const std::size_t vulkan_count = print_messages(ctx.validation_messages());
    const std::size_t openxr_count = print_messages(openxr);
    if (vulkan_count == 0 && openxr_count == 0) return;
    throw UserError(std::to_string(vulkan_count) + " Vulkan and " + std::to_string(openxr_count) +
                    " OpenXR validation message(s)");
}

}  // namespace monoplane::app
