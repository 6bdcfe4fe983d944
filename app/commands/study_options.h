// The options of `monoplane study ...`, shared by its subcommands (docs/study.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/commands/global_options.h"
#include "app/commands/study_headset.h"
#include "study/study_store.h"

namespace monoplane::app {

struct StudyOptions {
    std::string protocol;
    std::string participant;
    std::string db;
    std::vector<std::string> dbs;  // study list: every database of the study
    std::string headset = "none";
    std::string observer;  // "": default without a person (none, simulated), none with openxr
    std::string hmd = "vive";
    std::optional<std::uint64_t> seed;
    std::optional<int> session_number;       // --session N: the participant's session
    std::optional<std::int64_t> session_id;  // --session-id ID: the database's session id
    std::optional<int> participant_number;   // --participant-number N (1-based)
    std::vector<std::string> variables;      // --var NAME=VALUE
    // run: --abandon N "reason" (the participant's interrupted session N ends for good first)
    std::optional<std::pair<int, std::string>> abandon;
    std::string protocol_changed;  // run: --protocol-changed "reason"
    double pace_ms = 0.0;
    bool trace = false;                  // --trace
    bool trace_stop = false;             // --trace-stop (commit_trace.h)
    bool accept_changed_scenes = false;  // resume: go on although scene files changed
    std::string format = "csv";
    std::string out;
    bool force = false;  // export: overwrite a file that is not an earlier export of the kind
    bool json = false;   // list: JSON instead of a table
    std::string note;    // note: the text
    HeadsetStudyOptions headset_options;
};

// Choosing a session on the command line (resume, note): --session-id alone, or --participant
// with the participant's --session number. Each throws UserError naming the database.
void check_session_id_alone(const StudyOptions& o);
study::ParticipantRecord participant_record(const study::StudyStore& store, const StudyOptions& o);
std::int64_t participant_session_id(const study::ParticipantRecord& record, const StudyOptions& o,
                                    int session_number);

// The subcommands' work (study_session.cpp, study_roster.cpp). Each throws UserError with a
// message for the experimenter when it cannot go on.
void run_study(const StudyOptions& o, const GlobalOptions& global);
void resume_study(const StudyOptions& o, const GlobalOptions& global);
void export_study(const StudyOptions& o);
void list_study(const StudyOptions& o);
void note_study(const StudyOptions& o);
void migrate_study(const StudyOptions& o);

}  // namespace monoplane::app
