#include "study/request_names.h"

namespace monoplane::study {

const RequestNames& study_request_names() {
    static const RequestNames names{
        [](std::string_view number) { return "session " + std::string(number); },
        [](std::string_view number) {
            return number.empty() ? std::string("the participant number")
                                  : "participant number " + std::string(number);
        },
        [](std::string_view assignment) { return "variable " + std::string(assignment); },
    };
    return names;
}

}  // namespace monoplane::study
