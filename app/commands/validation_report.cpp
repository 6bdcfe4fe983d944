#include "app/commands/validation_report.h"

#include <iostream>
#include <string>

#include "common/result.h"

namespace monoplane::app {

void fail_on_validation_messages(const vk_core::Context& ctx, const GlobalOptions& global) {
    if (!global.validation || ctx.validation_messages().count() == 0) return;
    for (const auto& message : ctx.validation_messages().first_messages()) {
        std::cerr << message << "\n";
    }
    throw UserError(std::to_string(ctx.validation_messages().count()) +
                    " Vulkan validation message(s)");
}

}  // namespace monoplane::app
