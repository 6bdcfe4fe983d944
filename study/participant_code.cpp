#include "study/participant_code.h"

#include <algorithm>

namespace monoplane::study {

Result<void> check_participant_code(const std::string& code) {
    const bool ok = !code.empty() && code.size() <= kMaxParticipantCode &&
                    std::ranges::all_of(code, [](char c) {
                        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
                               (c >= '0' && c <= '9') || c == '_' || c == '-';
                    });
    if (ok) return Ok{};
    return Error{"participant code '" + code +
                 "' is invalid: use 1 to 64 letters, digits, '_' or '-' (a pseudonym such as P07, "
                 "never a name)"};
}

}  // namespace monoplane::study
