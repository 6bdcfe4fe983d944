// `monoplane devices`: the Vulkan devices, which one would be chosen, and why others would not.
#include <iostream>

#include "app/commands/commands.h"
#include "renderer/vk/context.h"

namespace monoplane::app {

void add_devices_command(CLI::App& root, const GlobalOptions& global) {
    CLI::App* cmd =
        root.add_subcommand("devices", "List Vulkan devices and the one --device picks");
    cmd->callback([&global] {
        vk_core::ContextOptions options;
        options.device_selector = global.device;
        options.validation = global.validation;
        auto ctx = vk_core::Context::create(options).value_or_throw();
        for (const vk_core::DeviceInfo& d : vk_core::describe_devices(ctx->instance())) {
            const bool chosen = d.index == ctx->device_info().index;
            std::cout << (chosen ? "* " : "  ") << d.index << ": " << d.name << " ("
                      << vk_core::device_type_name(d.type) << ", Vulkan "
                      << VK_API_VERSION_MAJOR(d.api_version) << "."
                      << VK_API_VERSION_MINOR(d.api_version) << ")";
            if (!d.suitable) std::cout << " unsuitable: " << d.unsuitable_reason;
            std::cout << "\n";
        }
    });
}

}  // namespace monoplane::app
