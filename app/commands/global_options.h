// Options every GPU command accepts.
#pragma once

#include <string>

#include "renderer/vk/context.h"

namespace monoplane::app {

struct GlobalOptions {
    std::string device;       // --device: index or part of a name (see `monoplane devices`)
    bool validation = false;  // --validation: Khronos validation layer; any message fails

    vk_core::ContextOptions context_options() const {
        vk_core::ContextOptions options;
        options.validation = validation;
        options.device_selector = device;
        return options;
    }
};

}  // namespace monoplane::app
