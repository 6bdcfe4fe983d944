#include "app/commands/runtime_lost.h"

namespace monoplane::app {
namespace {

// Where the session stood, as the experimenter would say it.
std::string position(const study::LiveScreen& screen, const study::LiveProgress& progress) {
    using study::ScreenKind;
    switch (screen.kind) {
        case ScreenKind::Instructions:
            return "on the instructions";
        case ScreenKind::Ready:
            return "on the ready screen";
        case ScreenKind::Break:
            return "in the break after trial " + std::to_string(progress.trial_number);
        case ScreenKind::Questionnaire:
            return "at the questionnaire";
        case ScreenKind::End:
        case ScreenKind::Finished:
            return "after the last trial";
        default:
            break;
    }
    if (progress.trial_number == 0) return "before the first trial";
    return "at trial " + std::to_string(progress.trial_number);
}

// A path as a shell takes it: quoted when it holds anything but the usual characters.
std::string shell_word(const std::string& text) {
    if (text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                               "_-./+:@=") == std::string::npos) {
        return text;
    }
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

}  // namespace

std::string runtime_lost_message(const study::LiveScreen& screen,
                                 const study::LiveProgress& progress,
                                 const study::SessionInfo& session, const std::filesystem::path& db,
                                 const std::string& headset) {
    return "the OpenXR runtime was lost " + position(screen, progress) + " of session " +
           std::to_string(session.session_number) +
           "; every decided trial is kept; resume with `monoplane study resume --db " +
           shell_word(db.string()) + " --participant " + shell_word(session.participant_code) +
           " --session " + std::to_string(session.session_number) + " --headset " + headset +
           "` (or the launcher's Resume)";
}

}  // namespace monoplane::app
