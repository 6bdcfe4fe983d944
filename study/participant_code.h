// The participant code: the pseudonym that is all the study database knows of a person. One rule
// and one message for every place that takes a code (the store, plan_session, the launcher's
// form), so a code refused in one is refused in the others with the same words.
#pragma once

#include <cstddef>
#include <string>

#include "common/result.h"

namespace monoplane::study {

inline constexpr std::size_t kMaxParticipantCode = 64;

// `[A-Za-z0-9_-]{1,64}`: short, with no room for a name. The message names the code and says
// what a code may hold. Pure; any time.
Result<void> check_participant_code(const std::string& code);

}  // namespace monoplane::study
