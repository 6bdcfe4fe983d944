#include "study/planned_trial_store.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace monoplane::study {

using sqlite::Statement;

Result<void> write_planned_trials(const sqlite::Connection& db, std::int64_t session_id,
                                  const Schedule& schedule) {
    Result<Statement> plan = Statement::prepare(
        db,
        "INSERT INTO planned_trials (session_id, trial_index, block, scene, label1_alternative, "
        "label1_mode, label2_mode) VALUES (?, ?, ?, ?, ?, ?, ?)");
    MONOPLANE_TRY(plan);
    for (const ScheduledTrial& t : schedule.trials) {
        if (!t.adaptive) continue;
        plan.value()
            .bind(1, session_id)
            .bind(2, t.index)
            .bind(3, t.block)
            .bind(4, t.scene)
            .bind(5, t.label1_alternative)
            .bind(6, render_mode_name(t.label1_mode))
            .bind(7, render_mode_name(t.label2_mode));
        MONOPLANE_TRY(plan.value().run("storing the staircase's planned trials"));
        plan.value().reset();
    }
    return Ok{};
}

Result<void> start_planned_trial(const sqlite::Connection& db, std::int64_t session_id,
                                 int trial_index, double m) {
    const std::string name =
        "trial " + std::to_string(trial_index) + " of session " + std::to_string(session_id);
    if (!(std::isfinite(m) && m > 0.0)) {
        return Error{name + ": the chosen mono plane is not a positive distance"};
    }
    Result<Statement> started =
        Statement::prepare(db, "SELECT 1 FROM trials WHERE session_id = ? AND trial_index = ?");
    MONOPLANE_TRY(started);
    started.value().bind(1, session_id).bind(2, trial_index);
    Result<bool> found = started.value().step("looking up " + name);
    MONOPLANE_TRY(found);
    if (*found) return Error{name + " has its mono plane already; a chosen m is never changed"};
    Result<Statement> copy = Statement::prepare(
        db,
        "INSERT INTO trials (session_id, trial_index, practice, block, scene, mono_plane, "
        "label1_alternative, label1_mode, label2_mode) SELECT session_id, trial_index, 0, block, "
        "scene, ?, label1_alternative, label1_mode, label2_mode FROM planned_trials "
        "WHERE session_id = ? AND trial_index = ?");
    MONOPLANE_TRY(copy);
    copy.value().bind(1, m).bind(2, session_id).bind(3, trial_index);
    MONOPLANE_TRY(copy.value().run("starting " + name));
    if (sqlite3_changes(db.get()) == 0) {
        return Error{name + " is not a staircase's planned trial in '" + db.path() + "'"};
    }
    return Ok{};
}

Procedure schedule_procedure(const Schedule& schedule) {
    const bool adaptive =
        std::ranges::any_of(schedule.trials, [](const ScheduledTrial& t) { return t.adaptive; });
    return adaptive ? Procedure::Staircase : Procedure::Constant;
}

Result<Procedure> parse_procedure(std::string_view name) {
    for (Procedure p : {Procedure::Constant, Procedure::Staircase}) {
        if (procedure_name(p) == name) return p;
    }
    return Error{"unknown procedure '" + std::string(name) + "' (written by a newer monoplane?)"};
}

}  // namespace monoplane::study
