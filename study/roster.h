// The study's roster: every participant and session of one or more databases with where it
// stands, including whether a process is running it now (`study list`, the launcher).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/result.h"
#include "study/session_hold.h"
#include "study/study_store.h"

namespace monoplane::study {

struct RosterEntry {
    std::filesystem::path database;
    RosterRow row;
    // The process running the session now; none when nobody is (a running or paused status
    // without a holder is an interrupted session: `study resume` continues it).
    std::optional<SessionHolder> holder;

    // "completed", "aborted", "running (process 12 on lab-pc since ...)", "interrupted".
    std::string state() const;
};

// Reads the roster of each database in turn (in the order given), sessions by participant code
// and session number. Errors name the database. Any time, also while sessions run.
Result<std::vector<RosterEntry>> read_roster(const std::vector<std::filesystem::path>& databases);
// The roster of one database through a store the caller has open (the launcher's snapshot).
Result<std::vector<RosterEntry>> read_roster(const StudyStore& store);

}  // namespace monoplane::study
