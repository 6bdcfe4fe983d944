// The analysis's input: plain rows, one per trial and one per questionnaire answer, whatever file
// they came from. The app converts a study database into these rows; read_export_csv() reads the
// CSV of `monoplane study export`. Keeping the rows plain keeps analysis/ free of the study
// library, SQLite and the renderer (docs/architecture.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "common/result.h"

namespace monoplane::analysis {

struct TrialRow {
    std::string source;  // the file it came from (database or CSV path)
    std::int64_t session_id = 0;
    std::string participant;  // pseudonymous code: the cluster for repeated measures
    std::string protocol;
    int trial_index = 0;
    bool practice = false;
    int block = -1;  // -1 for practice trials
    std::string scene;
    double mono_plane = 0.0;  // metres
    std::string label1_mode, label2_mode;
    std::string reference_mode;  // the protocol's first alternative (e.g. "stereo")
    std::string test_mode;       // the other one (e.g. "hybrid")
    bool decided = false;
    bool valid = false;
    std::string chosen_mode;  // "" if undecided
    bool chose_test = false;  // chosen_mode == test_mode
    int switches = 0;
    double decision_time_s = 0.0;
    std::string first_scene;  // scene of the session's first data block (order effects)
    // Headset sessions' frame log (database input only; 0 without one): frames the trial showed
    // and how many of them missed their display slot; the protocol's threshold for flagging.
    int frames_shown = 0;
    int frames_missed = 0;
    double missed_frame_threshold = 0.05;
};

struct AnswerRow {
    std::string source;
    std::int64_t session_id = 0;
    std::string participant;
    int item = 0;  // 0-based position in the protocol's questionnaire
    std::string text;
    int answer = 0;  // 1 .. scale_points
    int scale_points = 7;
};

struct Dataset {
    std::vector<TrialRow> trials;
    std::vector<AnswerRow> answers;
    std::vector<std::string> sources;  // in the order they were read
};

// Reads the CSV of `monoplane study export --format csv` (columns: study/export.cpp
// export_columns() and docs/data.md). Columns are found by header name, so later versions may
// add columns at the end. Practice and undecided trials are kept (analysable_trials() drops and
// counts them); the export has no questionnaire answers, so `answers` stays empty.
// reference_mode / test_mode / first_scene / chose_test come from derive_session_fields().
// Errors (a file that cannot be read, a missing column, a malformed field or record) name the
// file, the line and, for a field, the column.
Result<Dataset> read_export_csv(const std::filesystem::path& path);

// Appends another source. Sessions stay apart by (source, session_id): two databases may both
// have a session 1. Participants are *not* kept apart by source: a code is one person, the
// conservative choice for clustering (two people sharing a code merge into one, coarser
// cluster, which stays valid; one person split into two clusters would not).
void merge(Dataset& into, Dataset from);

// Fills, per session (source, session_id): first_scene = scene of the session's data trial in
// block 0; reference_mode = the one already set on any of the session's rows (a database
// reader knows the protocol's first alternative), else "stereo" when the session shows it,
// else the alphabetically first mode shown; test_mode = the other mode shown; chose_test =
// decided && chosen_mode == test_mode. Used by both readers. May be called more than once.
void derive_session_fields(std::vector<TrialRow>& trials);

}  // namespace monoplane::analysis
