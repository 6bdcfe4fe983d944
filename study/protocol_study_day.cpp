#include "study/protocol_study_day.h"

namespace monoplane::study {

// These names are protocol keys' values and appear in exports: never change one.
std::string_view variable_type_name(VariableType type) {
    switch (type) {
        case VariableType::Integer:
            return "integer";
        case VariableType::Number:
            return "number";
        case VariableType::Choice:
            return "choice";
        case VariableType::Text:
            return "text";
    }
    return "invalid";
}

std::string_view blocking_name(Blocking blocking) {
    return blocking == Blocking::None ? "none" : "scene";
}

}  // namespace monoplane::study
