// A note on a session for whoever reviews its data (docs/data.md, table session_notes).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace monoplane::study {

// Notes come from the software (a resume with changed scene files), from the experimenter's
// window while the session runs, or from `monoplane study note` afterwards.
enum class NoteSource { Software, Window, Command };
std::string_view note_source_name(NoteSource source);  // "software" | "window" | "command"

struct SessionNote {
    std::string noted_utc;  // ISO 8601 UTC; empty: add_note stamps the current time
    std::string text;
    NoteSource source = NoteSource::Software;
    // Written during a session: the session's clock (the runtime's time in a headset session,
    // the virtual clock headless) and the trial on screen or last shown; none otherwise.
    std::optional<std::int64_t> runtime_time_ns;
    std::optional<int> trial_index;

    bool operator==(const SessionNote&) const = default;
};

}  // namespace monoplane::study
