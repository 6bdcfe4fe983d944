// A headset session whose OpenXR runtime was lost (the instance or the session: a runtime that
// died or was quit, a broken connection to its service, a headset unplugged) ends as an ordinary
// interruption, not as a failure of monoplane or of the data: every decided trial is stored, the
// session is interrupted and resumes. main() prints the one message and exits with
// kExitRuntimeLost, so scripts and the launcher tell it from an error (exit 1).
#pragma once

#include <filesystem>
#include <string>

#include "common/result.h"
#include "study/live_session.h"
#include "study/study_store.h"

namespace monoplane::app {

// The exit status of `study run|resume` whose runtime was lost (docs/headsets.md).
inline constexpr int kExitRuntimeLost = 3;
// The exit statuses of `study run|resume`, for their --help.
inline constexpr const char* kSessionExitStatusHelp =
    "Exit status: 0 the session completed; 1 an error, or the session ended before the study "
    "did; 3 the OpenXR runtime or the session was lost: every decided trial is kept, and the "
    "session is interrupted and resumes (docs/headsets.md, \"When the runtime is lost\").";

// Thrown once the session is stored and OpenXR and Vulkan are torn down; caught by main() (exit
// kExitRuntimeLost) and, as any UserError, by the launcher, which shows its message.
class RuntimeLost : public UserError {
  public:
    using UserError::UserError;
};

// "the OpenXR runtime was lost at trial 2 of session 1; every decided trial is kept; resume with
// `monoplane study resume --db F --participant P --session 1 --headset openxr`": where the
// session stood (the screen and trial on show), that nothing decided is lost, and the command
// that continues it. Any time.
std::string runtime_lost_message(const study::LiveScreen& screen,
                                 const study::LiveProgress& progress,
                                 const study::SessionInfo& session, const std::filesystem::path& db,
                                 const std::string& headset);

}  // namespace monoplane::app
