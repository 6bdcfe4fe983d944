#include "study/store_validation.h"

#include <cmath>
#include <cstddef>
#include <set>
#include <string>

#include "study/protocol_study_day.h"

namespace monoplane::study {

Result<void> validate_schedule(const Schedule& schedule) {
    if (schedule.trials.empty()) return Error{"the schedule has no trials"};
    if (schedule.participant_index < 0)
        return Error{"the schedule's participant number is negative"};
    if (schedule.session_number < 1) return Error{"the schedule's session number is below 1"};
    for (const std::string& scene : schedule.block_order)
        if (scene.empty() || scene.find(',') != std::string::npos)
            return Error{"scene name '" + scene + "' in the block order is empty or has a comma"};
    for (std::size_t i = 0; i < schedule.trials.size(); ++i) {
        const ScheduledTrial& t = schedule.trials[i];
        const std::string where = "scheduled trial " + std::to_string(i) + ": ";
        if (t.index != static_cast<int>(i))
            return Error{where + "index " + std::to_string(t.index) + " is not its position"};
        if (t.practice != (t.block == -1))
            return Error{where + "practice trials have block -1 and data trials a block >= 0"};
        if (t.block < -1) return Error{where + "block is below -1"};
        if (t.scene.empty()) return Error{where + "no scene"};
        if (t.adaptive && (t.practice || !std::isnan(t.mono_plane)))
            return Error{where + "a staircase's trial is a data trial whose m is not chosen yet"};
        if (!t.adaptive && !std::isfinite(t.mono_plane))
            return Error{where + "mono plane is not finite"};
        if (t.label1_alternative != 0 && t.label1_alternative != 1)
            return Error{where + "label1_alternative must be 0 or 1"};
        if (t.repetition < 1) return Error{where + "repetition is below 1"};
    }
    return Ok{};
}

Result<void> validate_variables(const std::vector<VariableValue>& values) {
    std::set<std::string> seen;
    for (const VariableValue& v : values) {
        MONOPLANE_TRY(check_variable_name(v.name));
        if (!seen.insert(v.name).second)
            return Error{"participant variable '" + v.name + "' is given twice"};
    }
    return Ok{};
}

bool is_instruction_event(EventKind kind) {
    return kind == EventKind::InstructionsShown || kind == EventKind::InstructionsConfirmed;
}

Result<void> validate_event(const TrialEvent& event) {
    const auto kind = static_cast<std::size_t>(event.kind);
    if (kind > static_cast<std::size_t>(EventKind::RunStarted))
        return Error{"unknown event kind " + std::to_string(kind)};
    const std::string name(event_kind_name(event.kind));
    if (event.label < 0 || event.label > 2)
        return Error{"event label " + std::to_string(event.label) + " is not 0, 1 or 2"};
    if (event.frame < -1)
        return Error{"event frame " + std::to_string(event.frame) + " is below -1"};
    if (!is_trial_event(event.kind) && event.trial_index != -1)
        return Error{"a '" + name + "' event belongs to a screen or the session, not to trial " +
                     std::to_string(event.trial_index) + ": its trial index is -1"};
    if (has_detail(event.kind) && event.detail.find_first_not_of(" \t\n") == std::string::npos)
        return Error{"a '" + name + "' event needs its reason"};
    if (!has_detail(event.kind) && !event.detail.empty())
        return Error{"a '" + name + "' event has no reason to record"};
    if (is_trial_event(event.kind) && event.trial_index < 0)
        return Error{"a '" + name + "' event needs its trial (index " +
                     std::to_string(event.trial_index) + " given)"};
    if (is_instruction_event(event.kind) && event.page < 0)
        return Error{"a '" + name + "' event needs its instruction page (0-based; " +
                     std::to_string(event.page) + " given)"};
    if (!is_instruction_event(event.kind) && event.page != -1)
        return Error{"a '" + name + "' event has no instruction page (-1), not page " +
                     std::to_string(event.page)};
    return Ok{};
}

}  // namespace monoplane::study
