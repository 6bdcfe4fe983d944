// The same session is never counted twice. A copy of a study database (a backup beside the
// original, a file sent by e-mail, an export of it) holds the sessions of the original: given
// together, each decision would count twice and every test would look twice as sure. Sessions
// are known by their globally unique id (session_uuid), which every copy keeps, so a session
// that two inputs hold is found whatever the files are called; whether the copies are the same
// record is told by their trials.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/dataset.h"
#include "common/result.h"

namespace monoplane::analysis {

// A session of one input: (source, session_id), as sessions are kept apart everywhere.
struct SessionCopy {
    std::string source;
    std::int64_t session_id = 0;
};

// A later input's copy of a session that an earlier input holds too.
struct DuplicateSession {
    std::string session_uuid;
    std::string participant;
    int session_number = 1;
    SessionCopy first;  // the copy read first: the one counted when the copies are identical
    SessionCopy other;  // the later copy
    int trials = 0;     // trial rows of the first copy
    // How `other`'s trials differ from `first`'s, e.g. "backup.sqlite has 3 of the session's 8
    // trials decided, site-a.sqlite 8"; "" when they are the same trials with the same
    // decisions, switches and times.
    std::string difference;
};

// Every session whose session_uuid an earlier session of `data` has (in reading order),
// compared trial by trial with that first copy: the trials' scene, distance, labels,
// repetition, whether decided, the choice, validity, switches and decision time (to the
// nanosecond). Sessions without a session_uuid (exports of a monoplane before the column) are
// not compared. Any time; reads only.
std::vector<DuplicateSession> find_duplicate_sessions(const Dataset& data);

// Applies the rule to data: copies that differ are an error (also with `drop`) naming both files,
// the session and how they differ; identical copies are an error naming the files and the
// sessions unless `drop`, which removes every later copy (its trials, answers and session) and
// records them in data.dropped_copies. `drop_option` is how the caller's user asks for that
// ("--drop-duplicates"). Call before participant codes are joined: the copies' codes are the
// same.
Result<void> drop_duplicate_sessions(Dataset& data, bool drop, std::string_view drop_option);

}  // namespace monoplane::analysis
