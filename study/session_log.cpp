#include "study/session_log.h"

namespace monoplane::study {

Result<bool> MemorySessionLog::append_event(std::int64_t, const TrialEvent& event) {
    events_.push_back(event);
    return true;
}

Result<bool> MemorySessionLog::record_outcome(std::int64_t, int trial_index,
                                              const TrialOutcome& outcome) {
    if (!outcomes_.emplace(trial_index, outcome).second) {
        return Error{"trial " + std::to_string(trial_index) +
                     " is already decided; a recorded decision is never overwritten"};
    }
    return true;
}

Result<bool> MemorySessionLog::set_status(std::int64_t, SessionStatus status) {
    status_ = status;
    return true;
}

Result<bool> MemorySessionLog::record_answer(std::int64_t, int item, const std::string&,
                                             int answer) {
    answers_[item] = answer;  // asked again: the latest answer counts, as in the database
    return true;
}

}  // namespace monoplane::study
