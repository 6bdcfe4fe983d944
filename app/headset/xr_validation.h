// The OpenXR core validation layer (XR_APILAYER_LUNARG_core_validation, Debian's
// openxr-layer-corevalidation), the OpenXR counterpart of Vulkan's validation layer: with
// `--validation`, monoplane enables it on its XrInstance and collects what it reports through an
// XR_EXT_debug_utils messenger; any message fails the command, exactly as a
// Vulkan validation message does.
//
// Use: before xrCreateInstance, `XrValidation::plan(requested)` says which layer and extension
// to enable (or why it cannot); after it, `attach(instance)` creates the messenger. Messages may
// arrive on any thread the application calls OpenXR from; counting is thread-safe.
#pragma once

#include <openxr/openxr.h>

#include <memory>
#include <string>
#include <vector>

#include "common/result.h"
#include "renderer/vk/context.h"

namespace monoplane::headset {

inline constexpr const char* kXrValidationLayer = "XR_APILAYER_LUNARG_core_validation";

class XrValidation {
  public:
    // What to pass to xrCreateInstance. Refuses (with what to install) when validation is
    // requested but the layer is not installed, or the loader offers no XR_EXT_debug_utils.
    // Nothing to enable when not requested. Call before the instance exists.
    static Result<XrValidation> plan(bool requested);

    // The layer, unless XR_ENABLE_API_LAYERS already names it (the loader enables it then).
    const std::vector<const char*>& layers() const { return layers_; }
    const std::vector<const char*>& extensions() const { return extensions_; }
    bool enabled() const { return !extensions_.empty(); }

    // Creates the messenger on the instance made with layers() and extensions(). Any message at
    // warning severity or above is recorded. Call once, right after xrCreateInstance; the
    // messenger lives until detach() or the instance's destruction.
    Result<void> attach(XrInstance instance);
    // Destroys the messenger; call before xrDestroyInstance. Safe to call twice.
    void detach();

    // Messages recorded so far (shared: survives moves of this object).
    const vk_core::ValidationMessages& messages() const { return *messages_; }

  private:
    std::vector<const char*> layers_;
    std::vector<const char*> extensions_;
    std::shared_ptr<vk_core::ValidationMessages> messages_ =
        std::make_shared<vk_core::ValidationMessages>();
    XrInstance instance_ = XR_NULL_HANDLE;
    XrDebugUtilsMessengerEXT messenger_ = XR_NULL_HANDLE;
};

}  // namespace monoplane::headset
