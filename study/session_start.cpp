#include "study/session_start.h"

#include <algorithm>
#include <map>

namespace monoplane::study {
namespace {

// What the database already knows about the participant and their study-wide numbers.
struct Known {
    std::optional<ParticipantRecord> participant;
    int participant_count = 0;
    std::map<int, std::string> code_by_number;  // participant numbers in use
    std::string database = "DATABASE";          // for the commands the messages suggest
};

Result<Known> look_up(const StudyStore* store, const std::string& code) {
    Known known;
    if (store == nullptr) return known;
    known.database = store->path().string();
    Result<std::optional<ParticipantRecord>> participant = store->participant(code);
    MONOPLANE_TRY(participant);
    known.participant = *participant;
    Result<int> count = store->participant_count();
    MONOPLANE_TRY(count);
    known.participant_count = *count;
    Result<std::vector<RosterRow>> roster = store->roster();
    MONOPLANE_TRY(roster);
    for (const RosterRow& row : *roster)
        known.code_by_number.emplace(row.participant_number, row.participant_code);
    return known;
}

std::string participant_text(const std::string& code) {
    return "participant " + code;
}

// The command that continues a participant's (interrupted) session: the way on these messages
// show, spelled as the user types it, whichever caller asked.
std::string resume_command(const Known& known, const std::string& code,
                           std::optional<int> session = std::nullopt) {
    return "study resume --db " + known.database + " --participant " + code +
           (session ? " --session " + std::to_string(*session) : std::string());
}

void check_session_number(const SessionRequest& r, const Protocol& protocol, const Known& known,
                          const RequestNames& names, int& number,
                          std::vector<std::string>& problems) {
    const int next = known.participant ? known.participant->next_session_number() : 1;
    number = r.session_number.value_or(next);
    const std::string who = participant_text(r.participant_code);
    const std::string given = names.session(std::to_string(number));
    if (number < 1) {
        problems.push_back(given + ": sessions are numbered from 1");
    } else if (number < next) {
        problems.push_back(
            given + ": " + who + " already has session " + std::to_string(number) +
            "; to continue it: " + resume_command(known, r.participant_code, number));
    } else if (number > next && !known.participant) {
        // Their earlier sessions ran on another PC: the row they were given there goes on.
        if (!r.participant_number) {
            problems.push_back(given + ": " + who + " has no session in " + known.database +
                               " yet; to continue sessions run on another PC, also give " +
                               names.participant_number("") +
                               " (their number there), so their scene order goes on");
        }
    } else if (number > next) {
        problems.push_back(given + ": " + who + " has " + std::to_string(next - 1) +
                           " session(s); the next is session " + std::to_string(next));
    } else if (number > protocol.day.sessions) {
        problems.push_back(
            who + " already has " + std::to_string(number - 1) + " session(s), and protocol '" +
            protocol.name + "' has sessions = " + std::to_string(protocol.day.sessions) +
            " per participant (study list --db " + known.database +
            " shows whether one was interrupted: " + resume_command(known, r.participant_code) +
            ")");
    }
}

// The 0-based number that picks the Latin-square row.
void check_participant_number(const SessionRequest& r, const Known& known,
                              const RequestNames& names, int& number,
                              std::vector<std::string>& problems) {
    if (known.participant) {
        number = known.participant->participant_number;
        if (r.participant_number && *r.participant_number - 1 != number) {
            problems.push_back(names.participant_number(std::to_string(*r.participant_number)) +
                               ": " + participant_text(r.participant_code) +
                               " is participant number " + std::to_string(number + 1) +
                               " since their first session");
        }
        return;
    }
    number = r.participant_number ? *r.participant_number - 1 : known.participant_count;
    if (r.participant_number && *r.participant_number < 1) {
        problems.push_back(names.participant_number(std::to_string(*r.participant_number)) +
                           ": participants are numbered from 1");
        return;
    }
    if (const auto taken = known.code_by_number.find(number); taken != known.code_by_number.end()) {
        problems.push_back("participant number " + std::to_string(number + 1) +
                           " is taken by participant " + taken->second +
                           " in this database; give " + names.participant_number("N") +
                           " with a free number");
    }
}

// A returning participant's variables are theirs: given again, they must not differ.
void check_returning_variables(const SessionRequest& r, const Protocol& protocol,
                               const RequestNames& names, const ParticipantRecord& participant,
                               std::vector<VariableValue>& values,
                               std::vector<std::string>& problems) {
    values = participant.variables;
    for (const std::string& assignment : r.variables) {
        const auto eq = assignment.find('=');
        const std::string name = assignment.substr(0, eq);
        const auto declared =
            std::ranges::find(protocol.day.variables, name, &ParticipantVariable::name);
        const auto recorded = std::ranges::find(participant.variables, name, &VariableValue::name);
        if (eq == std::string::npos || declared == protocol.day.variables.end()) {
            // The recorded values stand for the required ones: only the name is in question.
            std::vector<ParticipantVariable> optional = protocol.day.variables;
            for (ParticipantVariable& v : optional) v.required = false;
            Result<std::vector<VariableValue>> one = check_variables(optional, {assignment}, names);
            if (!one) problems.push_back(one.error().message);
            continue;
        }
        Result<std::string> value =
            check_variable_value(*declared, assignment.substr(eq + 1), names);
        if (!value) {
            problems.push_back(value.error().message);
        } else if (recorded == participant.variables.end() || recorded->value != *value) {
            problems.push_back(names.variable(assignment) + ": " +
                               participant_text(r.participant_code) + " has " + name + " = " +
                               (recorded == participant.variables.end() ? std::string("no value")
                                                                        : recorded->value) +
                               " recorded at their first session; variables do not change");
        }
    }
}

std::string joined(const std::vector<std::string>& problems) {
    std::string text;
    for (const std::string& p : problems) text += (text.empty() ? "" : "\n") + p;
    return text;
}

}  // namespace

Result<SessionStart> plan_session(const StudyStore* store, const Protocol& protocol,
                                  const SessionRequest& r, const RequestNames& names) {
    MONOPLANE_TRY(check_participant_code(r.participant_code));
    Result<Known> known = look_up(store, r.participant_code);
    MONOPLANE_TRY(known);
    std::vector<std::string> problems;
    SessionStart start;
    start.new_participant = !known->participant;
    SessionInfo& info = start.info;
    check_session_number(r, protocol, *known, names, info.session_number, problems);
    check_participant_number(r, *known, names, info.participant_number, problems);
    if (known->participant) {
        check_returning_variables(r, protocol, names, *known->participant, info.variables,
                                  problems);
        info.participant_index = known->participant->participant_index;
    } else {
        Result<std::vector<VariableValue>> values =
            check_variables(protocol.day.variables, r.variables, names);
        if (!values)
            problems.push_back(values.error().message);
        else
            info.variables = *values;
        info.participant_index = known->participant_count;
    }
    if (store != nullptr && known->participant) {
        Result<std::vector<EarlierSession>> earlier = store->earlier_sessions(r.participant_code);
        MONOPLANE_TRY(earlier);
        Result<Admission> admitted = admit_session(
            AdmissionContext{.database = known->database, .participant_code = r.participant_code},
            *earlier,
            ProtocolVersion{
                .name = protocol.name, .text = protocol.text, .hash = protocol.text_hash},
            r.decisions);
        if (!admitted) problems.push_back(admitted.error().message);
    } else if (r.decisions.abandon_session || !r.decisions.protocol_change_reason.empty()) {
        problems.push_back("participant " + r.participant_code +
                           " has no earlier session here: --abandon and --protocol-changed are "
                           "for a participant's later sessions");
    }
    if (!problems.empty()) return Error{joined(problems)};
    info.decisions = r.decisions;
    info.participant_code = r.participant_code;
    info.protocol_name = protocol.name;
    info.protocol_hash = protocol.text_hash;
    info.protocol_text = protocol.text;
    info.seed = r.seed;
    info.render = protocol.render;
    start.schedule = make_schedule(protocol, r.seed, info.participant_number, info.session_number);
    return start;
}

}  // namespace monoplane::study
