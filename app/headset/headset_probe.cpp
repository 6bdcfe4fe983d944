#include "app/headset/headset_probe.h"

#include <openxr/openxr.h>

#include <memory>
#include <vector>

#include "app/headset/openxr_headset.h"

namespace monoplane::headset {
namespace {

// The launcher offers the simulated runtime (simxr) whenever the real one fails.
constexpr const char* kSimulatedOffered =
    " The simulated headset is available instead: choose 'simulated' for a dry run.";

}  // namespace

const char* eye_gaze_name(EyeGaze gaze) {
    switch (gaze) {
        case EyeGaze::Unknown:
            return "";
        case EyeGaze::NotOffered:
            return "not offered";
        case EyeGaze::NotTracked:
            return "not tracked";
        case EyeGaze::Tracked:
            return "tracked";
    }
    return "invalid";
}

std::string eye_gaze_text(EyeGaze gaze) {
    switch (gaze) {
        case EyeGaze::Unknown:
            return "";
        case EyeGaze::NotOffered:
            return "Eye gaze: not available, this OpenXR runtime offers no eye tracking "
                   "(protocols that record gaze record none)";
        case EyeGaze::NotTracked:
            return "Eye gaze: not tracked, the runtime offers eye tracking but this headset "
                   "has no eye tracker or it is switched off (protocols that record gaze "
                   "record none)";
        case EyeGaze::Tracked:
            return "Eye gaze: tracked (protocols that record gaze record it)";
    }
    return "";
}

EyeGaze eye_gaze_support(const OpenXrHeadset& headset) {
    if (headset.tracks_eye_gaze()) return EyeGaze::Tracked;
    return headset.offers_eye_gaze() ? EyeGaze::NotTracked : EyeGaze::NotOffered;
}

Result<HeadsetProbe> probe_runtime(bool validation) {
    HeadsetProbe probe;
    // No layer depth: the probe makes no session, and the extension must not be a reason to fail.
    // Eye gaze asked for: enabling the extension only asks the system whether it tracks the
    // eyes; nothing is sampled. Every failure here, a missing validation layer included (it
    // cannot be told apart from a missing runtime, whose extension list would offer
    // XR_EXT_debug_utils), is a message.
    Result<std::unique_ptr<OpenXrHeadset>> created =
        OpenXrHeadset::create(validation, false, /*eye_gaze=*/true);
    if (!created) {
        probe.message = created.error().message + "." + kSimulatedOffered;
        return probe;
    }
    const OpenXrHeadset& headset = *created.value();
    probe.runtime = headset.runtime_name();
    probe.system = headset.system_name();
    probe.eye_gaze = eye_gaze_support(headset);
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
