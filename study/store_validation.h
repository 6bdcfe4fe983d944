// Private to the study store: what it refuses before anything is written, in words a developer
// can act on. A schedule, a participant's variables or an event that got into the file would be
// stored for good; the table CHECKs (store_schema.cpp) are the last guard, these the first.
#pragma once

#include <vector>

#include "common/result.h"
#include "study/participant_variables.h"
#include "study/schedule.h"
#include "study/trial_events.h"

namespace monoplane::study {

// Trials numbered by position, practice in block -1, a staircase's trials without their m, scene
// names that the block order's column can hold. Pure; any time.
Result<void> validate_schedule(const Schedule& schedule);

// Values check_variables could have returned: names by check_variable_name's rule, each once.
// Pure; any time.
Result<void> validate_variables(const std::vector<VariableValue>& values);

// An event the events table's CHECKs would accept: a known kind, label and frame in range, a
// trial only for a trial's event, a reason only and always for the kinds that have one, a page
// only for the instruction pages' events. Pure; any time.
Result<void> validate_event(const TrialEvent& event);

// The events that belong to an instruction page (TrialEvent::page).
bool is_instruction_event(EventKind kind);

}  // namespace monoplane::study
