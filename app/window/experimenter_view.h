// What the experimenter window shows and what the experimenter can ask for: plain data, filled by
// the study loop every frame, so the window keeps no study state of its own.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace monoplane::window {

// Instructions, Ready, Break and End: the protocol's pages of text in the headset (End: the
// session is completed and the participant reads its last page).
enum class Phase {
    Starting,
    Trial,
    Neutral,
    Paused,
    Questionnaire,
    Finished,
    Aborted,
    Instructions,
    Ready,
    Break,
    End
};

struct ExperimenterView {
    std::string participant, protocol, headset, hmd, device;
    int trial_number = 0;  // 1-based; 0 before the first
    int trial_count = 0;
    bool practice = false;
    std::string scene;
    double mono_plane = 0.0;
    double elapsed_s = 0.0, trial_elapsed_s = 0.0;
    Phase phase = Phase::Starting;
    int visible_label = 0;  // 1 or 2 (0: none)
    int switches = 0;
    bool both_seen = false;
    bool unblinded = false;  // only then are label_modes shown
    std::array<std::string, 2> label_modes;
    std::vector<std::string> log_tail;  // newest last
    std::vector<std::string> questionnaire_items;
    int scale_points = 7;
    std::vector<int> answers;  // per item, 0 = not yet answered (Questionnaire phase)
    // Instructions, Ready, Break, End: the page the participant reads, as the headset shows it.
    std::string page_text;
    int page = 0;        // Instructions: the page shown, 0-based
    int page_count = 0;  // Instructions: how many pages
    // Break: the countdown as the headset shows it ("0:23"); empty once confirm continues.
    std::string break_countdown;
    // The outcome of the last note typed ("note stored at trial 12", or why it was not).
    std::string note_status;
    std::string status_line;
    // Eye gaze, in sessions that record it on a runtime that tracks the eyes: gaze_tracked, and
    // this frame's gaze point in the mirror's image (u right, v down, 0..1 across it, from
    // gaze_in_eye_image: outside 0..1 while the participant looks beyond the mirrored eye's
    // field); none while the tracker has no valid sample (a blink, the eyes lost).
    bool gaze_tracked = false;
    std::optional<std::array<double, 2>> gaze_uv;
    std::uint64_t frame_index = 0;
    double frame_ms = 0.0;
};

// One request of the experimenter (or of the keyboard in a desktop dry run). Answer carries
// `item` (0-based) and `value` (1..scale_points); Unblind carries value 1 (show the modes) or 0
// (hide them again); Note carries the note's `text`, to be stored at once. Switch and Confirm
// from one of the participant's answer keys ([responses], app/window/response_key_input.h) carry
// the key's X name in `key`; the experimenter's own keys and buttons leave it empty.
struct Command {
    enum class Kind {
        Switch,
        Confirm,
        Pause,
        Resume,
        Abort,
        Unblind,
        Answer,
        SubmitAnswers,
        Note
    } kind;
    int item = 0;
    int value = 0;
    std::string text = {};
    std::string key = {};
};

}  // namespace monoplane::window
