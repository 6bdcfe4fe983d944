// The end of every GPU command run with --validation: any validation message fails the command,
// with the first messages shown.
#pragma once

#include "app/commands/global_options.h"
#include "renderer/vk/context.h"

namespace monoplane::app {

// Throws UserError naming the count when validation was on and the Vulkan layer reported
// anything.
void fail_on_validation_messages(const vk_core::Context& ctx, const GlobalOptions& global);

// The same for both layers of a headset session: Vulkan's and OpenXR's core validation
// (app/headset/xr_validation.h). Every message of both is printed before the throw.
void fail_on_validation_messages(const vk_core::Context& ctx,
                                 const vk_core::ValidationMessages& openxr,
                                 const GlobalOptions& global);

}  // namespace monoplane::app
