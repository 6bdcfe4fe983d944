// `monoplane study run|resume`: sessions of the 2AFC study. With
// `--headset none` a simulated observer answers on a virtual clock: no rendering, a whole session
// in well under a second. With `--headset simulated|openxr` the session runs on an OpenXR headset
// (study_headset.h): monoplane's simulated runtime, or whichever runtime is active.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <random>
#include <utility>

#include "app/commands/commands.h"
#include "app/commands/option_wording.h"
#include "app/commands/session_summary.h"
#include "app/commands/simulated_gaze.h"
#include "app/commands/study_headset.h"
#include "app/commands/study_options.h"
#include "app/commands/study_rows.h"
#include "app/commands/study_scenes.h"
#include "app/version/build_info.h"
#include "hmd/profile.h"
#include "study/observer.h"
#include "study/protocol.h"
#include "study/schedule.h"
#include "study/session_hold.h"
#include "study/session_runner.h"
#include "study/session_start.h"
#include "study/staircase_estimates.h"
#include "study/study_store.h"

namespace monoplane::app {
namespace {

void check_headset(const std::string& headset) {
    if (headset == "none" || headset == "simulated" || headset == "openxr") return;
    throw UserError("--headset " + headset + ": use none, simulated or openxr");
}

// Who answers: a simulated observer unless a person holds the controller (openxr) or the
// simulated runtime's script plays the controller (`--observer none`).
std::string observer_for(const StudyOptions& o, const std::string& recorded = {}) {
    if (!o.observer.empty()) return o.observer;
    if (!recorded.empty()) return recorded;
    return o.headset == "openxr" ? "none" : "default";
}

// The observer's stimulus strength: the rig's projection error (study_rows.h), or for an observer
// that decides on the error where its gaze rests, that error under simxr's default gaze model
// (simulated_gaze.h) for the session's seed, on the scenes at the detail the session renders.
std::function<double(const study::ScheduledTrial&)> error_model(const StudyOptions& o,
                                                                const hmd::HmdProfile& hmd,
                                                                const study::Protocol& protocol,
                                                                const study::Observer* observer,
                                                                std::uint64_t seed) {
    if (!observer || !observer->decides_on_gaze_error()) return trial_error_model(hmd, protocol);
    study::Protocol shown = protocol;
    if (!o.headset_options.detail.empty()) shown.render.detail = o.headset_options.detail;
    std::shared_ptr<const SimulatedGaze> gaze = SimulatedGaze::build(shown, hmd).value_or_throw();
    return [gaze, seed](const study::ScheduledTrial& trial) {
        return gaze->error_at_gaze(trial, seed);
    };
}

CommitTrace commit_trace(const StudyOptions& o) {
    if (o.trace_stop) return CommitTrace::PrintAndStop;
    return o.trace ? CommitTrace::Print : CommitTrace::Off;
}

study::RunOptions run_options(const StudyOptions& o, const hmd::HmdProfile& hmd,
                              const study::Protocol& protocol, const study::Observer& observer,
                              std::uint64_t seed) {
    study::RunOptions options;
    options.pace_ns = static_cast<std::int64_t>(o.pace_ms * 1e6);
    options.neutral_ns = static_cast<std::int64_t>(o.headset_options.neutral_s * 1e9);
    options.trial_error_px = error_model(o, hmd, protocol, &observer, seed);
    if (const CommitTrace trace = commit_trace(o); trace != CommitTrace::Off) {
        options.on_committed = [trace](const std::string& what) { trace_committed(trace, what); };
    }
    return options;
}

// After a staircase session (or its part run now): each scene's threshold as its staircase
// estimates it from the stored decisions, so the experimenter sees at once whether a staircase
// converged. `trials`: the session's, as the store holds them now.
void print_staircase_estimates(const study::StudyStore& store, std::int64_t session_id,
                               const study::Protocol& protocol,
                               const std::vector<study::TrialRecord>& trials) {
    if (protocol.procedure != study::Procedure::Staircase) return;
    const study::SessionInfo info = store.session(session_id).value_or_throw();
    const auto estimates = study::final_staircase_estimates(info, trials).value_or_throw();
    for (const auto& [scene, estimate] : estimates) {
        std::fprintf(stderr, "staircase %s: threshold %.3g m", scene.c_str(), estimate.threshold_m);
        if (estimate.lower_m && estimate.upper_m) {
            std::fprintf(stderr, " (95 %% credible interval %.3g-%.3g m)", *estimate.lower_m,
                         *estimate.upper_m);
        }
        std::fprintf(stderr, " after %d trials\n", estimate.trials);
    }
}

// The session's summary (session_summary.h) on stderr: the same lines the launcher shows.
void print_summary(const study::StudyStore& store, std::int64_t session_id) {
    const SessionSummary summary = summarize_session(store, session_id).value_or_throw();
    for (const std::string& line : session_summary_lines(summary)) std::cerr << line << "\n";
}

void run_on_headset(
    const StudyOptions& o, const GlobalOptions& global, study::StudyStore& store,
    const study::Protocol& protocol, ImportedStudyScenes imported, study::Observer* observer,
    const hmd::HmdProfile& hmd, std::uint64_t seed,
    const std::function<std::int64_t(const std::string&, const std::string&)>& begin) {
    HeadsetStudyOptions options = o.headset_options;
    options.headset = o.headset;
    options.hmd = o.hmd;
    options.trace = commit_trace(o);
    std::optional<std::int64_t> session_id;
    const auto begin_and_note = [&](const std::string& runtime, const std::string& device) {
        session_id = begin(runtime, device);
        return *session_id;
    };
    const study::SessionStatus status =
        run_headset_session(options, global, store, protocol, std::move(imported), observer,
                            error_model(o, hmd, protocol, observer, seed), begin_and_note);
    if (!session_id) {
        std::cerr << "session " << study::session_status_name(status) << "\n";
        return;
    }
    print_summary(store, *session_id);
    if (protocol.procedure == study::Procedure::Staircase) {
        print_staircase_estimates(store, *session_id, protocol,
                                  store.trials(*session_id).value_or_throw());
    }
}

void finish(study::StudyStore& store, std::int64_t session_id, const study::Protocol& protocol,
            study::Observer& observer, const study::RunOptions& options) {
    // The summary reads the status the runner stored.
    study::run_session(store, session_id, protocol, observer, options).value_or_throw();
    print_summary(store, session_id);
    print_staircase_estimates(store, session_id, protocol,
                              store.trials(session_id).value_or_throw());
}

// The participant, session number, variables, seed and schedule, all checked before anything
// is written: a database that does not exist yet is not created for a refused session.
study::SessionStart plan(const StudyOptions& o, const study::Protocol& protocol,
                         const study::StudyStore* store) {
    study::SessionRequest request;
    request.participant_code = o.participant;
    request.session_number = o.session_number;
    request.participant_number = o.participant_number;
    request.variables = o.variables;
    request.seed = o.seed ? *o.seed : std::random_device{}() * 0x100000001ull;
    if (o.abandon) {
        request.decisions.abandon_session = o.abandon->first;
        request.decisions.abandon_reason = o.abandon->second;
    }
    request.decisions.protocol_change_reason = o.protocol_changed;
    return study::plan_session(store, protocol, request, study_run_option_names()).value_or_throw();
}

std::string session_title(const study::SessionInfo& info) {
    return "participant " + info.participant_code + ", session " +
           std::to_string(info.session_number);
}

}  // namespace

void run_study(const StudyOptions& o, const GlobalOptions& global) {
    check_headset(o.headset);
    const study::Protocol protocol = study::load_protocol(o.protocol).value_or_throw();
    const hmd::HmdProfile hmd = hmd::load_hmd_profile(o.hmd).value_or_throw();
    // Scene files are loaded and digested before anything is written: a broken file refuses the
    // session, and the digests go into the session's row with it.
    ImportedStudyScenes imported =
        load_imported_scenes(protocol.scene_files, protocol.source).value_or_throw();
    // Refused before anything is written: before a missing file is created, and before an
    // existing one is opened for writing (which would migrate an older schema).
    if (!std::filesystem::exists(o.db))
        plan(o, protocol, nullptr);
    else
        plan(o, protocol, study::StudyStore::open_read_only(o.db).value_or_throw().get());
    auto store = study::StudyStore::open(o.db).value_or_throw();
    study::SessionStart start = plan(o, protocol, store.get());
    study::SessionInfo& info = start.info;
    const study::Schedule& schedule = start.schedule;
    info.software_version = software_version();
    info.hmd = hmd.name;
    const std::string observer_name = observer_for(o);
    info.observer = observer_name == "none" ? "" : observer_name;
    // The protocol's [render] table, --detail overriding its detail; stored with the session,
    // which a headset loop (and a resume) renders with.
    if (!o.headset_options.detail.empty()) info.render.detail = o.headset_options.detail;
    info.scene_files = scene_file_records(imported);
    std::unique_ptr<study::Observer> observer;
    if (observer_name != "none")
        observer = study::make_observer(observer_name, info.seed).value_or_throw();
    if (o.headset == "none" && !observer)
        throw UserError("--headset none needs an observer to answer (not none)");
    std::optional<study::SessionHold> hold;
    // started_utc is left empty: the store stamps the session's start when it writes it.
    const auto begin = [&](const std::string& runtime, const std::string& device) {
        info.runtime = runtime;
        info.device = device;
        // Held before it commits: no other process ever sees it running without its holder.
        const std::int64_t id =
            store
                ->begin_session(info, schedule,
                                [&](std::int64_t new_id) -> Result<void> {
                                    Result<study::SessionHold> taken =
                                        study::SessionHold::acquire(o.db, new_id);
                                    MONOPLANE_TRY(taken);
                                    hold.emplace(std::move(taken).value());
                                    return Ok{};
                                })
                .value_or_throw();
        std::cerr << "session " << id << ": " << session_title(info) << " (participant number "
                  << info.participant_number + 1 << "), protocol " << protocol.name << ", seed "
                  << info.seed << ", " << schedule.trials.size() << " trials\n";
        return id;
    };
    if (o.headset != "none") {
        run_on_headset(o, global, *store, protocol, std::move(imported), observer.get(), hmd,
                       info.seed, begin);
        return;
    }
    imported.clear();  // recorded; nothing renders them without a headset
    const std::int64_t session_id = begin("none", "none");
    finish(*store, session_id, protocol, *observer,
           run_options(o, hmd, protocol, *observer, info.seed));
}

namespace {

// Which session `study resume` continues: --session-id ID; --participant CODE [--session N]
// (default: that participant's latest unfinished session); or the database's latest
// unfinished session.
std::int64_t session_to_resume(const StudyOptions& o, const study::StudyStore& store) {
    if (o.session_id) {
        check_session_id_alone(o);
        return *o.session_id;
    }
    if (o.session_number && o.participant.empty()) {
        throw UserError(
            "--session N is a participant's session number and goes with "
            "--participant CODE; to resume by the database's session id, use "
            "--session-id ID (study list shows both)");
    }
    if (!o.participant.empty()) {
        const study::ParticipantRecord record = participant_record(store, o);
        if (o.session_number) return participant_session_id(record, o, *o.session_number);
        for (auto it = record.sessions.rbegin(); it != record.sessions.rend(); ++it) {
            if (store.session(it->second).value_or_throw().status !=
                study::SessionStatus::Completed)
                return it->second;
        }
        throw UserError(o.db + ": participant " + o.participant +
                        " has no unfinished session to resume");
    }
    const auto latest = store.latest_unfinished_session().value_or_throw();
    if (!latest) throw UserError(o.db + ": no unfinished session to resume");
    return *latest;
}

}  // namespace

void resume_study(const StudyOptions& o, const GlobalOptions& global) {
    check_headset(o.headset);
    // Which session, judged on a snapshot first: a refused resume writes nothing (an older
    // schema is migrated only by a resume that goes ahead).
    const std::int64_t session_id = [&] {
        auto snapshot = study::StudyStore::open_read_only(o.db).value_or_throw();
        const std::int64_t id = session_to_resume(o, *snapshot);
        const study::SessionInfo found = snapshot->session(id).value_or_throw();
        if (found.status == study::SessionStatus::Completed) {
            throw UserError("session " + std::to_string(id) + " (" + session_title(found) +
                            ") is already completed");
        }
        return id;
    }();
    auto store = study::StudyStore::open_existing(o.db).value_or_throw();
    const study::SessionInfo info = store->session(session_id).value_or_throw();
    // A session another process is running is never taken over: its participant is in the
    // headset. The hold is the operating system's, so a dead process's session resumes at once.
    study::SessionHold hold = study::SessionHold::acquire(o.db, session_id).value_or_throw();
    // The holder may have finished it between the check above and the hold.
    if (store->session(session_id).value_or_throw().status == study::SessionStatus::Completed) {
        throw UserError("session " + std::to_string(session_id) + " (" + session_title(info) +
                        ") was completed just now by the process that ran it");
    }
    check_scene_files_before_resume(*store, info, o.accept_changed_scenes);
    // The protocol as it was when the session began, not the file as it is now; its scene files
    // where the session recorded them.
    study::Protocol protocol =
        study::parse_protocol(info.protocol_text, "session " + std::to_string(session_id))
            .value_or_throw();
    protocol.scene_files = study::recorded_scene_paths(info.scene_files);
    const hmd::HmdProfile hmd = hmd::load_hmd_profile(o.hmd).value_or_throw();
    const int first = store->first_undecided_trial(session_id).value_or_throw();
    std::cerr << "resuming session " << session_id << " (" << session_title(info) << ") at trial "
              << first << "\n";
    const std::string observer_name = observer_for(o, info.observer);
    std::unique_ptr<study::Observer> observer;
    if (observer_name != "none") {
        observer =
            study::make_observer(observer_name, info.seed ^ (0x9E3779B97F4A7C15ull * (first + 1)))
                .value_or_throw();
    }
    if (o.headset != "none") {
        ImportedStudyScenes imported =
            load_imported_scenes(protocol.scene_files, protocol.source).value_or_throw();
        run_on_headset(o, global, *store, protocol, std::move(imported), observer.get(), hmd,
                       info.seed,
                       [session_id](const std::string&, const std::string&) { return session_id; });
        return;
    }
    if (!observer) throw UserError("--headset none needs an observer to answer (not none)");
    finish(*store, session_id, protocol, *observer,
           run_options(o, hmd, protocol, *observer, info.seed));
}

}  // namespace monoplane::app
