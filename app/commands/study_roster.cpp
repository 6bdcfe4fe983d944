// `monoplane study export|list|note`: what a study has, for the experimenter and the analysis.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/commands/option_wording.h"
#include "app/commands/study_options.h"
#include "common/json_writer.h"
#include "study/export.h"
#include "study/roster.h"
#include "study/study_store.h"

namespace monoplane::app {
namespace {

std::string or_dash(const std::string& text) {
    return text.empty() ? "-" : text;
}

// Whether the session holds eye gaze, personal data the experimenter must account for: "yes"
// or "-".
const char* gaze_mark(const study::RosterRow& r) {
    return r.gaze ? "yes" : "-";
}

void print_roster_table(const std::vector<study::RosterEntry>& entries, bool several) {
    std::printf("%-12s %4s %7s %4s  %-11s %-16s %-20s %-20s %-14s %-10s %-4s %s\n", "participant",
                "no.", "session", "id", "trials", "protocol", "started", "ended", "device",
                "runtime", "gaze", "status");
    for (const study::RosterEntry& e : entries) {
        const study::RosterRow& r = e.row;
        const std::string trials =
            std::to_string(r.trials_decided) + "/" + std::to_string(r.trials_planned);
        std::printf(
            "%-12s %4d %7d %4lld  %-11s %-16s %-20s %-20s %-14s %-10s %-4s %s%s\n",
            r.participant_code.c_str(), r.participant_number + 1, r.session_number,
            static_cast<long long>(r.session_id), trials.c_str(),
            (r.protocol_name + " " + study::hash_text(r.protocol_hash).substr(8, 6)).c_str(),
            or_dash(r.started_utc).c_str(), or_dash(r.ended_utc).c_str(), or_dash(r.device).c_str(),
            or_dash(r.runtime).c_str(), gaze_mark(r), e.state().c_str(),
            several ? ("  " + e.database.string()).c_str() : "");
    }
}

void write_roster_json(const std::vector<study::RosterEntry>& entries) {
    JsonWriter json(JsonFormat{.indented = true});
    json.begin_object().begin_array("sessions");
    for (const study::RosterEntry& e : entries) {
        const study::RosterRow& r = e.row;
        json.begin_object()
            .value("database", e.database.string())
            .value("participant", r.participant_code)
            .value("participant_number", r.participant_number + 1)
            .value("session", r.session_number)
            .value("session_id", r.session_id)
            .value("status", std::string(study::session_status_name(r.status)))
            .value("state", e.state())
            .value("trials_decided", r.trials_decided)
            .value("trials_planned", r.trials_planned)
            .value("started_utc", r.started_utc);
        if (r.ended_utc.empty())
            json.null("ended_utc");
        else
            json.value("ended_utc", r.ended_utc);
        json.value("device", r.device)
            .value("runtime", r.runtime)
            .value("protocol", r.protocol_name)
            .value("protocol_hash", study::hash_text(r.protocol_hash))
            .value("session_uuid", r.session_uuid);
        if (r.abandoned_reason)
            json.value("abandoned_reason", *r.abandoned_reason);
        else
            json.null("abandoned_reason");
        if (e.holder) {
            json.begin_object("held_by")
                .value("pid", static_cast<std::int64_t>(e.holder->pid))
                .value("host", e.holder->host)
                .value("since_utc", e.holder->since_utc)
                .end_object();
        } else {
            json.null("held_by");
        }
        json.value("gaze", r.gaze);
        json.end_object();
    }
    json.end_array().end_object();
    std::cout << json.str();
}

}  // namespace

void check_session_id_alone(const StudyOptions& o) {
    if (!o.participant.empty() || o.session_number)
        throw UserError(
            "--session-id names a session alone: leave out --participant and --session");
}

study::ParticipantRecord participant_record(const study::StudyStore& store, const StudyOptions& o) {
    std::optional<study::ParticipantRecord> record =
        store.participant(o.participant).value_or_throw();
    if (!record) throw UserError(o.db + ": no participant " + o.participant);
    return std::move(*record);
}

std::int64_t participant_session_id(const study::ParticipantRecord& record, const StudyOptions& o,
                                    int session_number) {
    for (const auto& [number, id] : record.sessions)
        if (number == session_number) return id;
    throw UserError(o.db + ": participant " + o.participant + " has no session " +
                    std::to_string(session_number));
}

void export_study(const StudyOptions& o) {
    const study::ExportFormat format = study::parse_export_format(o.format).value_or_throw();
    // Before the database is opened (which would create a missing one): a refused --out changes
    // nothing, and a study database is never overwritten by its own export.
    check_output_option(o.out, export_option_kind(format), {o.db}, o.force).value_or_throw();
    auto store = study::StudyStore::open_read_only(o.db).value_or_throw();
    // Written to a temporary file and renamed: a failed export leaves no truncated file.
    study::export_trials(*store, format, std::filesystem::path(o.out), o.force, output_option_error)
        .value_or_throw();
    std::cerr << "wrote " << o.out << "\n";
}

void list_study(const StudyOptions& o) {
    std::vector<std::filesystem::path> databases(o.dbs.begin(), o.dbs.end());
    const auto entries = study::read_roster(databases).value_or_throw();
    if (o.json) {
        write_roster_json(entries);
        return;
    }
    if (entries.empty()) {
        std::cout << "no sessions yet\n";
        return;
    }
    print_roster_table(entries, databases.size() > 1);
}

namespace {

// Which session a note is for (--session-id, or --participant with --session).
std::int64_t session_for_note(const study::StudyStore& store, const StudyOptions& o) {
    std::int64_t session_id = 0;
    if (o.session_id) {
        check_session_id_alone(o);
        session_id = *o.session_id;
        store.session(session_id).value_or_throw();  // an unknown id is an error naming it
    } else {
        if (o.participant.empty())
            throw UserError(
                "say which session the note is for: --participant CODE [--session N] (N: "
                "that participant's session number) or --session-id ID (study list shows both)");
        const study::ParticipantRecord record = participant_record(store, o);
        session_id = participant_session_id(
            record, o, o.session_number.value_or(record.next_session_number() - 1));
    }
    return session_id;
}

}  // namespace

void note_study(const StudyOptions& o) {
    study::SessionNote note;
    note.text = o.note;
    note.source = study::NoteSource::Command;
    // Judged on a snapshot first: a refused note writes nothing (an older schema is migrated
    // only by a note that is stored).
    const std::int64_t session_id = [&] {
        auto snapshot = study::StudyStore::open_read_only(o.db).value_or_throw();
        const std::int64_t id = session_for_note(*snapshot, o);
        snapshot->check_note(id, note).value_or_throw();
        return id;
    }();
    auto store = study::StudyStore::open_existing(o.db).value_or_throw();
    store->add_note(session_id, note).value_or_throw();
    std::cerr << "note stored for session " << session_id << "\n";
}

}  // namespace monoplane::app
