#include "study/scene_file_store.h"

#include <algorithm>
#include <optional>
#include <set>
#include <utility>

namespace monoplane::study {
namespace {

using sqlite::Statement;

std::optional<NoteSource> parse_note_source(std::string_view name) {
    for (NoteSource source : {NoteSource::Software, NoteSource::Window, NoteSource::Command})
        if (note_source_name(source) == name) return source;
    return std::nullopt;
}

Result<void> validate_record(const SceneFileRecord& record, const Schedule& schedule) {
    const std::string where = "scene file record of '" + record.scene + "' (file " +
                              std::to_string(record.file_index) + "): ";
    if (std::ranges::find(schedule.block_order, record.scene) == schedule.block_order.end())
        return Error{where + "the schedule shows no such scene"};
    if (!names_scene_file(record.scene))
        return Error{where + "the scene does not name a .gltf or .glb file"};
    if (record.file_index < 0) return Error{where + "the file index is negative"};
    if (record.path.empty() || !record.path.is_absolute())
        return Error{where + "the path '" + record.path.string() + "' is not absolute"};
    if (!is_sha256_hex(record.digest.sha256))
        return Error{where + "'" + record.digest.sha256 +
                     "' is not a SHA-256 digest in 64 lowercase hex digits"};
    return Ok{};
}

}  // namespace

Result<void> validate_scene_files(const std::vector<SceneFileRecord>& records,
                                  const Schedule& schedule) {
    std::set<std::pair<std::string, int>> seen;
    for (const SceneFileRecord& record : records) {
        MONOPLANE_TRY(validate_record(record, schedule));
        if (!seen.insert({record.scene, record.file_index}).second)
            return Error{"scene file record of '" + record.scene + "' (file " +
                         std::to_string(record.file_index) + ") is listed twice"};
    }
    for (const std::string& scene : schedule.block_order) {
        if (names_scene_file(scene) && !seen.contains({scene, 0}))
            return Error{"scene '" + scene +
                         "' names a glTF file but no record of the file itself (file 0) was "
                         "given: a session with an imported scene keeps its digests"};
    }
    return Ok{};
}

Result<void> write_scene_files(const sqlite::Connection& db, std::int64_t session_id,
                               const std::vector<SceneFileRecord>& records) {
    Result<Statement> insert = Statement::prepare(
        db,
        "INSERT INTO scene_files (session_id, scene, file_index, path, size_bytes, sha256) "
        "VALUES (?, ?, ?, ?, ?, ?)");
    MONOPLANE_TRY(insert);
    for (const SceneFileRecord& r : records) {
        Statement& s = insert.value();
        s.reset();
        s.bind(1, session_id).bind(2, r.scene).bind(3, r.file_index).bind(4, r.path.string());
        s.bind(5, static_cast<std::int64_t>(r.digest.size_bytes)).bind(6, r.digest.sha256);
        MONOPLANE_TRY(s.run("recording the files of scene '" + r.scene + "'"));
    }
    return Ok{};
}

Result<void> write_session_note(const sqlite::Connection& db, std::int64_t session_id,
                                const SessionNote& note) {
    Result<Statement> insert = Statement::prepare(
        db,
        "INSERT INTO session_notes (session_id, noted_utc, note, source, runtime_time_ns, "
        "trial_index) VALUES (?, ?, ?, ?, ?, ?)");
    MONOPLANE_TRY(insert);
    insert.value().bind(1, session_id).bind(2, note.noted_utc).bind(3, note.text);
    insert.value().bind(4, note_source_name(note.source)).bind(5, note.runtime_time_ns);
    insert.value().bind(6, note.trial_index);
    return insert.value().run("adding a note to session " + std::to_string(session_id) +
                              " (the session must exist)");
}

Result<std::vector<SceneFileRecord>> read_scene_files(const sqlite::Connection& db,
                                                      std::int64_t session_id) {
    Result<Statement> stmt =
        Statement::prepare(db,
                           "SELECT scene, file_index, path, size_bytes, sha256 FROM scene_files "
                           "WHERE session_id = ? ORDER BY rowid");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, session_id);
    std::vector<SceneFileRecord> records;
    for (;;) {
        Result<bool> row = stmt.value().step("reading a session's scene files");
        MONOPLANE_TRY(row);
        if (!*row) break;
        const Statement& s = stmt.value();
        records.push_back({s.text(0), s.int32(1), s.text(2),
                           FileDigest{static_cast<std::uint64_t>(s.int64(3)), s.text(4)}});
    }
    return records;
}

Result<std::vector<SessionNote>> read_session_notes(const sqlite::Connection& db,
                                                    std::int64_t session_id) {
    Result<Statement> stmt = Statement::prepare(
        db,
        "SELECT noted_utc, note, source, runtime_time_ns, trial_index FROM session_notes "
        "WHERE session_id = ? ORDER BY id");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, session_id);
    std::vector<SessionNote> notes;
    for (;;) {
        Result<bool> row = stmt.value().step("reading a session's notes");
        MONOPLANE_TRY(row);
        if (!*row) break;
        const Statement& s = stmt.value();
        const std::optional<NoteSource> source = parse_note_source(s.text(2));
        if (!source)
            return Error{"study database '" + db.path() +
                         "' holds a note from an unknown source '" + s.text(2) +
                         "' (written by a newer monoplane?)"};
        SessionNote note;
        note.noted_utc = s.text(0);
        note.text = s.text(1);
        note.source = *source;
        if (!s.is_null(3)) note.runtime_time_ns = s.int64(3);
        if (!s.is_null(4)) note.trial_index = s.int32(4);
        notes.push_back(std::move(note));
    }
    return notes;
}

}  // namespace monoplane::study
