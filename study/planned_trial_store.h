// Private to the study store: the planned_trials table (schema version 5; docs/data.md). A
// staircase session's data trials are slots whose mono plane is chosen only when each starts;
// their seeded order, scenes and blind labels are still stored before the first trial, here, in
// begin_session's transaction. A slot becomes a row of `trials`, copied from its plan with the
// chosen m, when its trial starts (record_stimulus); a slot whose staircase stopped stays a plan.
#pragma once

#include <cstdint>
#include <string_view>

#include "common/result.h"
#include "study/protocol_staircase.h"
#include "study/schedule.h"
#include "study/store_sqlite.h"

namespace monoplane::study {

// The schedule's adaptive trials as plans, inside the caller's open transaction.
Result<void> write_planned_trials(const sqlite::Connection& db, std::int64_t session_id,
                                  const Schedule& schedule);

// The trial row of a started slot: its plan with mono plane m, inside the caller's open
// transaction. Refuses a slot that is not planned, one that has started already, and an m that
// is not a finite positive distance.
Result<void> start_planned_trial(const sqlite::Connection& db, std::int64_t session_id,
                                 int trial_index, double m);

// The slots of session ?1 not started yet, as the store's trial columns (store_reads.cpp
// kTrialColumns): no mono plane (NULL), undecided, a staircase's, repetition 1, runs 1.
inline constexpr std::string_view kUnstartedPlannedTrials =
    "SELECT pt.trial_index, 0, pt.block, pt.scene, NULL, pt.label1_alternative, "
    "pt.label1_mode, pt.label2_mode, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL, 1, 1, 1 "
    "FROM planned_trials pt WHERE pt.session_id = ?1 AND NOT EXISTS (SELECT 1 FROM trials t "
    "WHERE t.session_id = pt.session_id AND t.trial_index = pt.trial_index)";

// The procedure a schedule was made for: staircase when it has adaptive trials.
Procedure schedule_procedure(const Schedule& schedule);
Result<Procedure> parse_procedure(std::string_view name);

}  // namespace monoplane::study
