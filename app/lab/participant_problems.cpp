// LauncherModel::find_participant_problems and the launcher's names for a request's inputs: what
// keeps a participant from starting, said at the Participant step where it is fixed, with the
// window's fields and buttons, where `study run` would name its options.
#include <algorithm>
#include <string>

#include "app/lab/launcher_model.h"

namespace monoplane::lab {

const study::RequestNames& launcher_request_names() {
    static const study::RequestNames names{
        [](std::string_view number) { return "session " + std::string(number); },
        [](std::string_view number) {
            return number.empty() || number == "N" ? std::string("the participant number")
                                                   : "participant number " + std::string(number);
        },
        [](std::string_view assignment) {
            const std::string_view name = assignment.substr(0, assignment.find('='));
            return "the '" + std::string(name) + "' field";
        },
    };
    return names;
}

namespace {

bool unfinished(const RosterLine& line) {
    return line.state.rfind("interrupted", 0) == 0 || line.state.rfind("running", 0) == 0;
}

std::string session_problem(const std::string& code, const RosterLine& line) {
    const study::RosterRow& row = line.entry.row;
    const std::string session = "session " + std::to_string(row.session_number);
    if (line.entry.holder) {
        return code + "'s " + session + " is " + line.state +
               ": wait until it ends there, or type another participant code";
    }
    return code + "'s " + session + " was interrupted (" + std::to_string(row.trials_decided) +
           " of " + std::to_string(row.trials_planned) +
           " trials): press Resume on its line in the sessions list below, or type another "
           "participant code";
}

}  // namespace

void LauncherModel::find_participant_problems() {
    participant_problems_.clear();
    if (!protocol_ || code_.empty() || !code_message_.empty()) return;
    for (const VariableField& field : fields_) {
        const study::ParticipantVariable& v = field.declaration;
        if (field.recorded || !v.required || !field.text.empty()) continue;
        participant_problems_.push_back("fill in '" + v.name + "'" +
                                        (v.help.empty() ? std::string() : " (" + v.help + ")") +
                                        " above: it is required");
    }
    if (!participant_) return;
    for (const RosterLine& line : roster_) {
        if (line.entry.row.participant_code == code_ && unfinished(line)) {
            participant_problems_.push_back(session_problem(code_, line));
            return;  // the session limit waits for this one
        }
    }
    const int done = participant_->next_session_number() - 1;
    if (!session_number_ && done >= protocol_->day.sessions) {
        participant_problems_.push_back(
            code_ + " has had all " + std::to_string(protocol_->day.sessions) +
            " session(s) of protocol '" + protocol_->name +
            "': type another participant code, or choose another protocol in step 2");
    }
}

void LauncherModel::choose_protocol_named(const std::string& name) {
    const auto same = [&](const ProtocolChoice& c) { return c.valid && c.name == name; };
    if (std::ranges::count_if(protocols_, same) != 1) return;  // none or ambiguous: ask
    (void)select_protocol(std::ranges::find_if(protocols_, same)->path);
}

}  // namespace monoplane::lab
