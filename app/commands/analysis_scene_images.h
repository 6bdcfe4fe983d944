// The pictures under the report's gaze densities (docs/gaze.md, "The report's gaze section"):
// the view the densities are drawn in, the seat's left eye of the sessions' HMD profile, and each
// scene with gaze rendered from there (its default viewpoint), as the participants' sessions
// showed it (their detail, their glTF files). Rendering needs a Vulkan device; without one, or
// when a scene cannot be loaded, the report draws the density alone and its caption says why.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "analysis/gaze_projection.h"
#include "analysis/report/gaze_results.h"
#include "hmd/profile.h"
#include "study/study_store.h"

namespace monoplane::app {

// What the sessions of the inputs say about how their scenes were shown.
struct GazeViewSource {
    std::vector<std::string> hmds;  // study::SessionInfo::hmd of each session, as recorded
    std::string detail;             // the first session's [render] detail
    std::map<std::string, std::filesystem::path> scene_files;  // glTF scenes entry -> file
};

// Adds one database's sessions to `source`.
void add_sessions(GazeViewSource& source,
                  const std::map<std::int64_t, study::SessionInfo>& sessions);

// The seat's left eye: the built-in profile whose name the first session recorded, else "vive"
// (a profile read from a file is not known by its name; `note` then says so).
struct SeatView {
    hmd::HmdProfile profile;
    std::string key;  // the built-in's name ("vive")
    analysis::SeatEye eye;
    std::string note;  // "" when the sessions' profile was found
};
SeatView seat_view(const GazeViewSource& source);

// Renders the left eye of every scene of gaze.densities at the seat and stores it in
// gaze.images; where that is not possible, gaze.image_note says why. Never fails.
void add_scene_images(analysis::report::GazeResults& gaze, const GazeViewSource& source,
                      const SeatView& view);

}  // namespace monoplane::app
