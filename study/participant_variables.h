// Participant variables (protocol [[variables]]): the values an experimenter gives as
// NAME=VALUE (`study run --var`, or the launcher's form), checked against the protocol's
// declarations before any trial, and stored with the participant.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"
#include "study/protocol_study_day.h"
#include "study/request_names.h"

namespace monoplane::study {

// One recorded value: the declaration's name and type, and the value in its canonical text
// (integers without sign or leading zeros beyond what they need, numbers as number_text writes
// them, choices and text as given).
struct VariableValue {
    std::string name;
    VariableType type = VariableType::Text;
    std::string value;

    bool operator==(const VariableValue&) const = default;
};

// Checks `assignments` ("NAME=VALUE") against the declarations and returns the values in
// declaration order (variables not given are left out). Every problem is reported at once, one
// per line, each naming the variable (as `names` says it) and what is allowed: an unknown name
// (with "did you mean"), a name given twice, a value that is not an integer / number, out of its
// range or not among the choices, an empty or over-long text (more than 1000 characters, or with
// a control character other than tab), a required variable not given. Pure; any time.
Result<std::vector<VariableValue>> check_variables(
    const std::vector<ParticipantVariable>& declarations,
    const std::vector<std::string>& assignments, const RequestNames& names = study_request_names());

// One value alone (the launcher validates each field as it is typed): the canonical text, or
// the problem in the words check_variables uses.
Result<std::string> check_variable_value(const ParticipantVariable& declaration,
                                         std::string_view value,
                                         const RequestNames& names = study_request_names());

}  // namespace monoplane::study
