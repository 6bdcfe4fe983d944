// Private to the study store: the rows of the scene_files and session_notes tables (schema
// version 3, notes' source, session time and trial since version 7; docs/data.md). The evidence
// of which files a session's imported scenes were read from is written in begin_session's
// transaction, so no session exists without it; notes are appended later (by the software, the
// experimenter's window or `study note`) and never edited.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/result.h"
#include "study/scene_files.h"
#include "study/schedule.h"
#include "study/store_sqlite.h"
#include "study/study_store.h"

namespace monoplane::study {

// Refuses records that cannot be evidence of this schedule's scenes, before anything is written:
// a record of a scene the schedule does not show, a scene that is no file name, a relative or
// empty path, a digest not in sha256sum's form, a repeated (scene, file_index); and a scene of
// the schedule that names a glTF file but has no record of its own file (file_index 0).
Result<void> validate_scene_files(const std::vector<SceneFileRecord>& records,
                                  const Schedule& schedule);

// Inside the caller's open transaction.
Result<void> write_scene_files(const sqlite::Connection& db, std::int64_t session_id,
                               const std::vector<SceneFileRecord>& records);
Result<void> write_session_note(const sqlite::Connection& db, std::int64_t session_id,
                                const SessionNote& note);

// A session's records and notes, each in the order they were written.
Result<std::vector<SceneFileRecord>> read_scene_files(const sqlite::Connection& db,
                                                      std::int64_t session_id);
Result<std::vector<SessionNote>> read_session_notes(const sqlite::Connection& db,
                                                    std::int64_t session_id);

}  // namespace monoplane::study
