#include "study/session_admission.h"

#include <cstdio>

#include "study/protocol_design.h"

namespace monoplane::study {
namespace {

bool unfinished(const EarlierSession& s) {
    return s.status == SessionStatus::Running || s.status == SessionStatus::Paused;
}

std::string session_text(const AdmissionContext& c, int number) {
    return "participant " + c.participant_code + "'s session " + std::to_string(number) + " in '" +
           c.database + "'";
}

Error running(const AdmissionContext& c, const EarlierSession& s) {
    return Error{session_text(c, s.session_number) + " is running: " + s.holder->describe() +
                 ". A participant runs one session at a time: wait until it ends there, or stop "
                 "that process and resume it."};
}

Error interrupted(const AdmissionContext& c, const EarlierSession& s) {
    const std::string n = std::to_string(s.session_number);
    return Error{session_text(c, s.session_number) + " was interrupted (" +
                 std::to_string(s.trials_decided) + " of " + std::to_string(s.trials_planned) +
                 " trials decided). Resume it: monoplane study resume --db " + c.database +
                 " --participant " + c.participant_code + " --session " + n +
                 " (the launcher: Resume); or end it for good and start the next: study run ... "
                 "--abandon " +
                 n + " \"reason\"."};
}

// The rule of one live session; returns the session --abandon ends, if any.
Result<std::optional<std::int64_t>> check_live(const AdmissionContext& c,
                                               const std::vector<EarlierSession>& earlier,
                                               const StartDecisions& d) {
    std::optional<std::int64_t> abandon;
    for (const EarlierSession& s : earlier) {
        if (!unfinished(s)) continue;
        if (s.holder) return running(c, s);
        if (d.abandon_session != s.session_number) return interrupted(c, s);
        abandon = s.id;
    }
    if (d.abandon_session && !abandon) {
        return Error{"--abandon " + std::to_string(*d.abandon_session) + ": " +
                     session_text(c, *d.abandon_session) +
                     " is not an interrupted session (only those can be abandoned; study list "
                     "shows each session's state)."};
    }
    if (abandon && d.abandon_reason.find_first_not_of(" \t\n") == std::string::npos)
        return Error{"--abandon: give the reason the session ends, e.g. --abandon " +
                     std::to_string(*d.abandon_session) + " \"participant felt unwell\""};
    return abandon;
}

std::string hash_hex(std::uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

// How `protocol` differs from the participant's latest session that counts (not abandoned):
// a change accepted once (with its reason) is the design their next sessions are held to.
struct Comparison {
    const EarlierSession* session = nullptr;
    std::vector<std::string> design;  // empty: only the text differs
};

std::optional<Comparison> compare_with_latest(const std::vector<EarlierSession>& earlier,
                                              std::optional<std::int64_t> abandoning,
                                              const ProtocolVersion& protocol) {
    const EarlierSession* latest = nullptr;
    for (const EarlierSession& s : earlier)
        if (!s.abandoned && s.id != abandoning &&
            (latest == nullptr || s.session_number > latest->session_number))
            latest = &s;
    if (latest == nullptr || latest->protocol_hash == protocol.hash) return std::nullopt;
    Result<Protocol> theirs =
        parse_protocol(latest->protocol_text, "session " + std::to_string(latest->session_number));
    Result<Protocol> ours = parse_protocol(protocol.text, "the new session");
    if (!theirs || !ours)
        return Comparison{latest,
                          {"a protocol no longer reads (" +
                           (theirs ? ours.error() : theirs.error()).message + ")"}};
    return Comparison{latest, design_differences(*theirs, *ours)};
}

Result<std::optional<TrialEvent>> check_protocol(const AdmissionContext& c,
                                                 const std::vector<EarlierSession>& earlier,
                                                 std::optional<std::int64_t> abandoning,
                                                 const ProtocolVersion& protocol,
                                                 const StartDecisions& d) {
    const bool reason_given =
        d.protocol_change_reason.find_first_not_of(" \t\n") != std::string::npos;
    const std::optional<Comparison> diff = compare_with_latest(earlier, abandoning, protocol);
    const bool design_changed = diff && !diff->design.empty();
    if (!design_changed && !d.protocol_change_reason.empty())
        return Error{"--protocol-changed: protocol '" + protocol.name +
                     "' has the design of participant " + c.participant_code +
                     "'s earlier sessions; leave the option out."};
    if (!diff) return std::optional<TrialEvent>();
    const std::string n = std::to_string(diff->session->session_number);
    TrialEvent event;
    event.trial_index = -1;
    if (!design_changed) {
        event.kind = EventKind::ProtocolTextChanged;
        event.detail = "protocol text differs from session " + n + "'s (hash " +
                       hash_hex(diff->session->protocol_hash) + " -> " + hash_hex(protocol.hash) +
                       "); the design is the same";
        return std::optional<TrialEvent>(event);
    }
    const std::string how = describe_differences(diff->design);
    if (!reason_given)
        return Error{"protocol '" + protocol.name + "' differs in design from " +
                     session_text(c, diff->session->session_number) + ": " + how +
                     ". Sessions of one participant share a design; if the change is intended, "
                     "give --protocol-changed \"reason\" (it is recorded with the session)."};
    event.kind = EventKind::ProtocolChanged;
    event.detail =
        d.protocol_change_reason + " (design differs from session " + n + "'s: " + how + ")";
    return std::optional<TrialEvent>(event);
}

}  // namespace

Result<Admission> admit_session(const AdmissionContext& context,
                                const std::vector<EarlierSession>& earlier,
                                const ProtocolVersion& protocol, const StartDecisions& decisions) {
    Result<std::optional<std::int64_t>> abandon = check_live(context, earlier, decisions);
    MONOPLANE_TRY(abandon);
    Result<std::optional<TrialEvent>> change =
        check_protocol(context, earlier, *abandon, protocol, decisions);
    MONOPLANE_TRY(change);
    return Admission{.abandon_id = *abandon, .protocol_event = *change};
}

}  // namespace monoplane::study
