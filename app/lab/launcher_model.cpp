#include "app/lab/launcher_model.h"

#include <algorithm>
#include <system_error>

#include "study/observer.h"
#include "study/participant_variables.h"
#include "study/scene_files.h"
#include "study/session_hold.h"

namespace monoplane::lab {
namespace {

namespace fs = std::filesystem;

// The verdict `protocol check` prints for the file's text (its scene files are not loaded).
ProtocolChoice judge_protocol(const fs::path& path) {
    ProtocolChoice choice;
    choice.path = path;
    choice.file = path.filename().string();
    Result<study::Protocol> protocol = study::load_protocol(path);
    choice.valid = protocol.ok();
    if (protocol)
        choice.name = protocol->name;
    else
        choice.message = protocol.error().message;
    return choice;
}

// What `study resume` would say about an unfinished session that nobody holds: its scene files
// are read again with the check resume makes (study::changed_scene_files).
Result<void> judge_resume(const study::StudyStore& store, RosterLine& line) {
    const study::RosterRow& row = line.entry.row;
    if (row.status == study::SessionStatus::Completed) return Ok{};
    if (line.entry.holder) {
        line.resume_refusal = "session " + std::to_string(row.session_id) + " is being run by " +
                              line.entry.holder->describe() +
                              "; wait until it ends there, or stop that process and resume it";
        return Ok{};
    }
    Result<study::SessionInfo> info = store.session(row.session_id);
    MONOPLANE_TRY(info);
    const std::vector<study::SceneFileChange> changes =
        study::changed_scene_files(info->scene_files);
    if (changes.empty()) {
        line.resume_offered = true;
        return Ok{};
    }
    line.scene_files_changed = true;
    line.resume_refusal = "scene files changed since session " + std::to_string(row.session_id) +
                          " began, so its remaining trials would show other scenes than its "
                          "first:";
    for (const study::SceneFileChange& change : changes)
        line.resume_refusal += "\n  " + study::describe(change);
    line.resume_refusal +=
        "\nRestore the files, or resume with changed scenes (the session's notes will record it).";
    return Ok{};
}

// The problem with a field's text, in check_variable_value's words; none while it is empty
// (the Participant step names a required one that is still missing). A decimal comma is
// refused as `study run --var` refuses it, never read as a thousands separator or dropped: the
// message shows the number with a point, so "6,5" is never stored as 65.
std::string field_message(const VariableField& field, const study::RequestNames& names) {
    if (field.text.empty()) return {};
    Result<std::string> value = study::check_variable_value(field.declaration, field.text, names);
    if (value) return {};
    std::string pointed = field.text;
    std::ranges::replace(pointed, ',', '.');
    if (field.declaration.type == study::VariableType::Number && pointed != field.text &&
        study::check_variable_value(field.declaration, pointed, names)) {
        return names.variable(field.declaration.name + "=" + field.text) + ": write " + pointed +
               " (the decimal point is '.'; a comma is not read as one)";
    }
    return value.error().message;
}

// The folder's *.toml files with their times and sizes, or "missing": what changes when a
// protocol is saved, added or removed, or the folder comes or goes.
std::string folder_signature(const fs::path& folder) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) return "missing";
    std::vector<std::string> files;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->path().extension() != ".toml") continue;
        std::error_code ignored;
        const auto time = fs::last_write_time(it->path(), ignored).time_since_epoch().count();
        files.push_back(it->path().filename().string() + ":" + std::to_string(time) + ":" +
                        std::to_string(it->file_size(ignored)));
    }
    std::ranges::sort(files);
    std::string signature;
    for (const std::string& file : files) signature += file + "\n";
    return signature;
}

std::string running_message() {
    return "a session is running: it ends in its own window (closing that window keeps it "
           "resumable)";
}

}  // namespace

std::string_view step_name(LauncherStep step) {
    switch (step) {
        case LauncherStep::Database:
            return "database";
        case LauncherStep::Protocol:
            return "protocol";
        case LauncherStep::Participant:
            return "participant";
        case LauncherStep::Headset:
            return "headset";
        case LauncherStep::Session:
            return "session";
        case LauncherStep::Summary:
            return "summary";
    }
    return "database";
}

Result<std::vector<ProtocolChoice>> list_protocols(const fs::path& folder) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) {
        return Error{"protocols folder '" + folder.string() +
                     "' does not exist or is not a folder: give --protocols DIR, e.g. the "
                     "repository's protocols/"};
    }
    std::vector<ProtocolChoice> choices;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->path().extension() != ".toml" || !it->is_regular_file(ec)) continue;
        choices.push_back(judge_protocol(it->path()));
    }
    if (ec) return Error{"cannot read protocols folder '" + folder.string() + "': " + ec.message()};
    std::ranges::sort(choices, {}, &ProtocolChoice::file);
    return choices;
}

// The launcher reads the database through snapshots (StudyStore::open_read_only): Open, the
// roster and the participant's form change no byte of it; sessions write through their own
// store. Create makes a missing file a new study first.
Result<std::unique_ptr<study::StudyStore>> open_for_launcher(const fs::path& path, bool create) {
    std::error_code ec;
    if (create && !fs::exists(path, ec)) {
        Result<std::unique_ptr<study::StudyStore>> made = study::StudyStore::open(path);
        MONOPLANE_TRY(made);
    }
    return study::StudyStore::open_read_only(path);
}

// The roster lines of the launcher's snapshot `store` (one copy of the file for all of it).
Result<std::vector<RosterLine>> read_launcher_roster(const study::StudyStore& store) {
    Result<std::vector<study::RosterEntry>> entries = study::read_roster(store);
    MONOPLANE_TRY(entries);
    std::vector<RosterLine> lines;
    for (study::RosterEntry& entry : entries.value()) {
        RosterLine line;
        line.entry = std::move(entry);
        line.state = line.entry.state();
        MONOPLANE_TRY(judge_resume(store, line));
        lines.push_back(std::move(line));
    }
    return lines;
}

// Run: `study run` with the options the experimenter chose, in the order --help lists them;
// resume: `study resume` of one session by its id.
std::vector<std::string> LaunchRequest::arguments() const {
    std::vector<std::string> a;
    if (command == Command::Run) {
        a = {"study", "run", "--protocol", protocol, "--participant", participant, "--db", db};
        if (session_number) a.insert(a.end(), {"--session", std::to_string(*session_number)});
        for (const std::string& v : variables) a.insert(a.end(), {"--var", v});
        if (participant_number) {
            a.insert(a.end(), {"--participant-number", std::to_string(*participant_number)});
        }
    } else {
        a = {"study", "resume", "--db", db};
        if (session_id) a.insert(a.end(), {"--session-id", std::to_string(*session_id)});
        if (accept_changed_scenes) a.push_back("--accept-changed-scenes");
    }
    a.insert(a.end(), {"--headset", headset});
    if (!observer.empty()) a.insert(a.end(), {"--observer", observer});
    if (!keys.empty()) a.insert(a.end(), {"--keys", keys});
    if (seed && command == Command::Run) a.insert(a.end(), {"--seed", std::to_string(*seed)});
    a.insert(a.end(), session_arguments.begin(), session_arguments.end());
    if (preset) {
        const std::vector<std::string> chosen = study_run_arguments(*preset);
        for (std::size_t i = 0; i + 1 < chosen.size(); i += 2) {
            if (command == Command::Resume && chosen[i] == "--detail") continue;
            a.insert(a.end(), {chosen[i], chosen[i + 1]});
        }
    }
    return a;
}

LauncherModel::LauncherModel(LauncherSettings settings)
    : names_(std::move(settings.names)),
      session_arguments_(std::move(settings.session_arguments)),
      detail_option_(std::move(settings.detail)),
      scale_option_(settings.resolution_scale) {
    // Failures stay as the steps' messages: the window shows them where the choice is made.
    if (!settings.protocols.empty()) (void)scan_protocols(settings.protocols);
    if (!settings.db.empty() && open_database(settings.db, true)) step_ = LauncherStep::Protocol;
    revalidate();
}

LauncherModel::~LauncherModel() = default;
LauncherModel::LauncherModel(LauncherModel&&) noexcept = default;
LauncherModel& LauncherModel::operator=(LauncherModel&&) noexcept = default;

Result<void> LauncherModel::step_done(LauncherStep step) const {
    switch (step) {
        case LauncherStep::Database:
            if (store_) return Ok{};
            return Error{"open or create a study database first" +
                         (db_message_.empty() ? std::string() : ": " + db_message_)};
        case LauncherStep::Protocol:
            if (protocol_) return Ok{};
            return Error{"choose a valid protocol first"};
        case LauncherStep::Participant:
            if (!code_.empty() && code_message_.empty()) return Ok{};
            return Error{code_.empty() ? "enter the participant code first" : code_message_};
        default:
            return Ok{};
    }
}

Result<void> LauncherModel::go_to(LauncherStep step) {
    if (step == step_) return Ok{};
    if (step_ == LauncherStep::Session) return Error{running_message()};
    if (step == LauncherStep::Session || step == LauncherStep::Summary)
        return Error{"a session begins with Start (or Resume); its summary follows it"};
    if (step < step_) {
        step_ = step;
        return Ok{};
    }
    for (int s = 0; s < static_cast<int>(step); ++s) {
        MONOPLANE_TRY(step_done(static_cast<LauncherStep>(s)));
    }
    step_ = step;
    return Ok{};
}

Result<void> LauncherModel::open_database(const fs::path& path, bool create) {
    if (step_ == LauncherStep::Session) return Error{running_message()};
    std::error_code ec;
    Error problem;
    if (path.empty()) {
        problem.message = "choose a study database file (.sqlite)";
    } else if (!create && !fs::exists(path, ec)) {
        problem.message = "no study database '" + path.string() + "': choose Create to start one";
    } else if (Result<std::unique_ptr<study::StudyStore>> store = open_for_launcher(path, create);
               !store) {
        problem = store.error();
    } else {
        store_ = std::move(store).value();
        db_ = path;
        db_message_.clear();
        (void)read_roster_lines();    // its error becomes the database step's message
        set_participant_code(code_);  // a code known in one database may be new in another
        return Ok{};
    }
    // A failed choice leaves no database open, so nothing starts in the wrong file.
    store_.reset();
    roster_.clear();
    db_ = path;
    db_message_ = problem.message;
    set_participant_code(code_);
    return problem;
}

Result<void> LauncherModel::refresh_roster() {
    if (!store_) return Error{"open or create a study database first"};
    // A new snapshot: the one taken before a session does not hold it.
    Result<std::unique_ptr<study::StudyStore>> store = study::StudyStore::open_read_only(db_);
    if (!store) {
        db_message_ = store.error().message;
        return store.error();
    }
    store_ = std::move(store).value();
    return read_roster_lines();
}

Result<void> LauncherModel::read_roster_lines() {
    Result<std::vector<RosterLine>> roster = read_launcher_roster(*store_);
    if (!roster) {
        db_message_ = roster.error().message;
        return roster.error();
    }
    roster_ = std::move(roster).value();
    return Ok{};
}

Result<void> LauncherModel::scan_protocols(const fs::path& folder) {
    if (step_ == LauncherStep::Session) return Error{running_message()};
    protocols_dir_ = folder;
    protocols_signature_ = folder_signature(folder);
    Result<std::vector<ProtocolChoice>> choices = list_protocols(folder);
    protocols_ = choices ? std::move(choices).value() : std::vector<ProtocolChoice>{};
    protocols_message_ = choices ? std::string() : choices.error().message;
    MONOPLANE_TRY(choices);
    return Ok{};
}

bool LauncherModel::rescan_protocols_if_changed() {
    if (step_ == LauncherStep::Session || protocols_dir_.empty()) return false;
    if (folder_signature(protocols_dir_) == protocols_signature_) return false;
    (void)scan_protocols(protocols_dir_);  // a failure is the step's message
    return true;
}

Result<void> LauncherModel::select_protocol(const fs::path& path) {
    if (step_ == LauncherStep::Session) return Error{running_message()};
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return Error{"no protocol file '" + path.string() + "'"};
    ProtocolChoice judged = judge_protocol(path);  // the file as it is now
    auto listed = std::ranges::find(protocols_, path, &ProtocolChoice::path);
    if (listed != protocols_.end()) *listed = judged;
    if (!judged.valid) {
        // The experimenter chose this file: an earlier choice must not start in its place.
        protocol_.reset();
        protocol_path_.clear();
        rebuild_fields();
        rebuild_presets();
        revalidate();
        return Error{judged.message};
    }
    protocol_ = study::load_protocol(path).value();
    protocol_path_ = path;
    rebuild_fields();
    rebuild_presets();
    revalidate();
    return Ok{};
}

void LauncherModel::set_participant_code(const std::string& code) {
    code_ = code;
    participant_.reset();
    Result<void> valid = study::check_participant_code(code);
    code_message_ = code.empty() || valid ? std::string() : valid.error().message;
    if (valid && store_) {
        Result<std::optional<study::ParticipantRecord>> record = store_->participant(code);
        if (record)
            participant_ = *record;
        else
            code_message_ = record.error().message;
    }
    rebuild_fields();
    revalidate();
}

int LauncherModel::next_session_number() const {
    return participant_ ? participant_->next_session_number() : 1;
}

void LauncherModel::set_session_number(std::optional<int> number) {
    session_number_ = number;
    revalidate();
}

void LauncherModel::set_participant_number(std::optional<int> number) {
    participant_number_ = number;
    revalidate();
}

// A returning participant's fields show what was recorded, read-only; a new participant's keep
// what was typed for the same name, so changing the code or re-choosing the protocol loses
// nothing.
void LauncherModel::rebuild_fields() {
    std::vector<VariableField> fields;
    if (protocol_) {
        for (const study::ParticipantVariable& declaration : protocol_->day.variables) {
            VariableField field;
            field.declaration = declaration;
            if (participant_) {
                field.recorded = true;
                const auto value = std::ranges::find(participant_->variables, declaration.name,
                                                     &study::VariableValue::name);
                if (value != participant_->variables.end()) field.text = value->value;
            } else if (const auto typed = std::ranges::find(
                           fields_, declaration.name,
                           [](const VariableField& f) { return f.declaration.name; });
                       typed != fields_.end() && !typed->recorded) {
                field.text = typed->text;
            }
            field.message = field.recorded ? std::string() : field_message(field, names_);
            fields.push_back(std::move(field));
        }
    }
    fields_ = std::move(fields);
}

Result<void> LauncherModel::set_variable(const std::string& name, const std::string& text) {
    const auto field =
        std::ranges::find(fields_, name, [](const VariableField& f) { return f.declaration.name; });
    if (field == fields_.end()) {
        return Error{"the protocol declares no participant variable '" + name + "'"};
    }
    if (field->recorded) {
        return Error{"participant " + code_ + " has " + name +
                     " recorded at their first session; variables do not change"};
    }
    field->text = text;
    field->message = field_message(*field, names_);
    revalidate();
    return Ok{};
}

Result<void> LauncherModel::set_headset(const std::string& headset) {
    if (headset != "none" && headset != "simulated" && headset != "openxr")
        return Error{"headset '" + headset + "': choose none, simulated or openxr"};
    if (headset != headset_) {
        headset_report_ = HeadsetReport{};  // another runtime: probed again
        headset_probed_ = false;
    }
    headset_ = headset;
    revalidate();
    return Ok{};
}

void LauncherModel::set_headset_report(HeadsetReport report) {
    // The estimates were of the eyes the last report recommended.
    if (report.width != headset_report_.width || report.height != headset_report_.height)
        estimates_.clear();
    headset_report_ = std::move(report);
    headset_probed_ = true;
    revalidate();
}

Result<void> LauncherModel::next_participant() {
    if (step_ == LauncherStep::Session) return Error{running_message()};
    for (VariableField& field : fields_)
        if (!field.recorded) field.text.clear();
    session_number_.reset();
    participant_number_.reset();
    summary_.reset();
    set_participant_code("");  // rebuilds the (now empty) form and revalidates
    step_ = protocol_ ? LauncherStep::Participant : LauncherStep::Protocol;
    return Ok{};
}

// The observer is made as run_study makes it, so a name it would refuse is refused here.
Result<void> LauncherModel::set_observer(const std::string& observer) {
    if (!observer.empty() && observer != "none") {
        MONOPLANE_TRY(study::make_observer(observer, 0));
    }
    observer_ = observer;
    revalidate();
    return Ok{};
}

void LauncherModel::set_seed(std::optional<std::uint64_t> seed) {
    seed_ = seed;
    revalidate();
}

LaunchRequest LauncherModel::request() const {
    LaunchRequest r;
    r.protocol = protocol_path_.string();
    r.db = db_.string();
    r.participant = code_;
    r.session_number = session_number_;
    r.participant_number = participant_number_;
    // A returning participant's recorded values are theirs already: `study run` takes none.
    for (const VariableField& field : fields_) {
        if (!field.recorded && !field.text.empty())
            r.variables.push_back(field.declaration.name + "=" + field.text);
    }
    r.seed = seed_;
    r.headset = headset_;
    r.observer = observer_;
    r.session_arguments = session_arguments_;
    if (const PerformancePreset* chosen = preset()) r.preset = *chosen;
    r.keys = keys_;
    return r;
}

namespace {

// The request as run_study hands it to plan_session (the seed changes the schedule, never
// whether the session may start).
study::SessionRequest session_request(const LaunchRequest& r) {
    study::SessionRequest s;
    s.participant_code = r.participant;
    s.session_number = r.session_number;
    s.participant_number = r.participant_number;
    s.variables = r.variables;
    s.seed = r.seed.value_or(0);
    return s;
}

}  // namespace

void LauncherModel::revalidate() {
    find_participant_problems();
    std::string problems;
    for (const std::string& problem : participant_problems_)
        problems += (problems.empty() ? "" : "\n") + problem;
    if (!store_) {
        start_message_ = "open or create a study database first";
    } else if (!protocol_) {
        start_message_ = "choose a valid protocol first";
    } else if (code_.empty()) {
        start_message_ = "enter the participant code";
    } else if (!problems.empty()) {
        start_message_ = problems;
    } else if (headset_ != "none" && headset_probed_ && !headset_report_.runtime_available) {
        start_message_ = "no runtime for the " + headset_ + " headset (" +
                         (headset_report_.message.empty() ? std::string("no OpenXR runtime")
                                                          : headset_report_.message) +
                         "): choose another headset above";
    } else {
        Result<study::SessionStart> plan =
            study::plan_session(store_.get(), *protocol_, session_request(request()), names_);
        start_message_ = plan ? std::string() : plan.error().message;
    }
}

Result<LaunchRequest> LauncherModel::start() {
    if (step_ == LauncherStep::Session) return Error{running_message()};
    revalidate();  // another PC or process may have written since the last keystroke
    if (!start_enabled()) return Error{start_message_};
    Result<study::SessionStart> plan =
        study::plan_session(store_.get(), *protocol_, session_request(request()), names_);
    MONOPLANE_TRY(plan);
    launched_session_number_ = plan->info.session_number;
    launched_ = request();
    summary_.reset();
    step_ = LauncherStep::Session;
    return *launched_;
}

Result<LaunchRequest> LauncherModel::resume(std::int64_t session_id, bool accept_changed_scenes) {
    if (step_ == LauncherStep::Session) return Error{running_message()};
    MONOPLANE_TRY(refresh_roster());
    const auto line = std::ranges::find(roster_, session_id,
                                        [](const RosterLine& l) { return l.entry.row.session_id; });
    if (line == roster_.end())
        return Error{"no session " + std::to_string(session_id) + " in " + db_.string()};
    const study::RosterRow& row = line->entry.row;
    if (row.status == study::SessionStatus::Completed) {
        return Error{"session " + std::to_string(session_id) + " (participant " +
                     row.participant_code + ", session " + std::to_string(row.session_number) +
                     ") is already completed"};
    }
    const bool accepted = line->scene_files_changed && !line->entry.holder && accept_changed_scenes;
    if (!line->resume_offered && !accepted) return Error{line->resume_refusal};
    if (!protocol_) choose_protocol_named(row.protocol_name);
    LaunchRequest r;
    r.command = LaunchRequest::Command::Resume;
    r.session_arguments = session_arguments_;
    r.db = db_.string();
    r.session_id = session_id;
    r.accept_changed_scenes = accepted;
    r.headset = headset_;
    r.observer = observer_;
    if (const PerformancePreset* chosen = preset()) r.preset = *chosen;
    r.keys = keys_;
    launched_session_number_ = row.session_number;
    launched_ = r;
    summary_.reset();
    step_ = LauncherStep::Session;
    return r;
}

Result<void> LauncherModel::session_ended(const std::string& error) {
    if (step_ != LauncherStep::Session || !launched_)
        return Error{"no session was started from the launcher"};
    SessionOutcome summary;
    summary.error = error;
    summary.state = "not started";
    summary.participant = launched_->participant;
    summary.session_number = launched_session_number_;
    std::optional<std::int64_t> id = launched_->session_id;
    Result<void> fresh = refresh_roster();  // the session's rows are in the next snapshot
    if (!id && store_) {
        Result<std::optional<std::int64_t>> found =
            store_->find_session(launched_->participant, launched_session_number_);
        MONOPLANE_TRY(found);
        id = *found;
    }
    step_ = LauncherStep::Summary;
    set_participant_code(code_);  // their sessions and next number have changed
    summary_ = summary;
    MONOPLANE_TRY(fresh);
    const auto line = std::ranges::find(roster_, id.value_or(0),
                                        [](const RosterLine& l) { return l.entry.row.session_id; });
    if (line == roster_.end()) return Ok{};  // refused before its first row was written
    const study::RosterRow& row = line->entry.row;
    summary_->session_id = row.session_id;
    summary_->participant = row.participant_code;
    summary_->session_number = row.session_number;
    summary_->state = line->state;
    summary_->trials_decided = row.trials_decided;
    summary_->trials_planned = row.trials_planned;
    summary_->started_utc = row.started_utc;
    summary_->ended_utc = row.ended_utc;
    return Ok{};
}

}  // namespace monoplane::lab
