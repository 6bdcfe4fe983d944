#include "app/headset/headset_probe.h"

#include <memory>

#include "app/headset/openxr_headset.h"

namespace monoplane::headset {
namespace {

// The launcher offers the simulated runtime (simxr) whenever the real one fails.
constexpr const char* kSimulatedOffered =
    " The simulated headset is available instead: choose 'simulated' for a dry run.";

}  // namespace

Result<HeadsetProbe> probe_runtime(bool validation) {
    HeadsetProbe probe;
    // No layer depth: the probe makes no session, and the extension must not be a reason to fail.
    // Every failure here, a missing validation layer included (it cannot be told apart from a
    // missing runtime, whose extension list would offer XR_EXT_debug_utils), is a message.
    Result<std::unique_ptr<OpenXrHeadset>> created = OpenXrHeadset::create(validation, false);
    if (!created) {
        probe.message = created.error().message + "." + kSimulatedOffered;
        return probe;
    }
    const OpenXrHeadset& headset = *created.value();
    probe.runtime = headset.runtime_name();
    probe.system = headset.system_name();
    const Result<vk::Extent2D> extent = headset.recommended_eye_extent();
    if (!extent) {
        probe.message = "the OpenXR runtime '" + probe.runtime +
                        "' reports no stereo views: " + extent.error().message + "." +
                        kSimulatedOffered;
        return probe;
    }
    probe.width = static_cast<int>(extent->width);
    probe.height = static_cast<int>(extent->height);
    probe.runtime_available = true;
    if (const std::size_t count = headset.validation_messages().count(); count > 0) {
        return Error{std::to_string(count) + " OpenXR validation message(s) while probing '" +
                     probe.runtime +
                     "', the first: " + headset.validation_messages().first_messages().front()};
    }
    return probe;
}

}  // namespace monoplane::headset
