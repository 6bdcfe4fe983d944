// How messages about a session request name its inputs. The study library names them in its own
// words ("session 2", "participant number 3", "variable age=17"); a caller whose users give them
// otherwise (the command line's --session 2, --participant-number 3, --var age=17) passes names
// that say them so, and the same checks read in its words. Why not a structured error instead:
// one request has many problems at once, each a sentence around these names.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace monoplane::study {

struct RequestNames {
    // A session number as given ("2"), or "N" where a message shows how to give one.
    std::function<std::string(std::string_view number)> session;
    // A participant number as given ("3", or "N"); "" names the input itself.
    std::function<std::string(std::string_view number)> participant_number;
    // A variable as given, NAME=VALUE ("age=17"), or "age=VALUE" to show how to give one.
    std::function<std::string(std::string_view assignment)> variable;
};

// The library's own names: "session 2", "participant number 3" ("the participant number" for
// ""), "variable age=17".
const RequestNames& study_request_names();

}  // namespace monoplane::study
