#include "analysis/report/study_day_section.h"

#include <algorithm>
#include <map>
#include <set>

#include "analysis/report/html_format.h"
#include "charts/svg_writer.h"

namespace monoplane::analysis::report {
namespace {

using charts::xml_escaped;

template <typename T>
void add_once(std::vector<T>& list, const T& item) {
    if (std::find(list.begin(), list.end(), item) == list.end()) list.push_back(item);
}

// Free text as HTML: escaped, its line breaks kept.
std::string text_html(const std::string& text) {
    std::string out;
    for (char c : xml_escaped(text)) {
        if (c == '\r') continue;
        out += c == '\n' ? std::string("<br>") : std::string(1, c);
    }
    return out;
}

// The values of one variable over a participant's sessions, distinct, in session order.
std::string joined_values(const std::vector<const SessionRow*>& sessions, const std::string& name) {
    std::vector<std::string> values;
    for (const SessionRow* s : sessions)
        for (const auto& [variable, value] : s->variables)
            if (variable == name) add_once(values, value);
    std::string out;
    for (const std::string& value : values) out += (out.empty() ? "" : " / ") + value;
    return out;
}

std::vector<ParticipantDetail> participant_details(const std::vector<SessionRow>& sessions,
                                                   const std::vector<std::string>& names) {
    std::map<std::string, std::vector<const SessionRow*>> by_participant;
    for (const SessionRow& s : sessions) by_participant[s.participant].push_back(&s);
    const std::map<std::string, const SessionRow*> first = first_sessions(sessions);
    std::vector<ParticipantDetail> out;
    for (auto& [participant, list] : by_participant) {
        std::stable_sort(list.begin(), list.end(), [](const SessionRow* a, const SessionRow* b) {
            return a->session_number < b->session_number;
        });
        ParticipantDetail d;
        d.participant = participant;
        for (const SessionRow* s : list) {
            add_once(d.session_numbers, s->session_number);
            add_once(d.sources, s->source);
        }
        const SessionRow& earliest = *first.at(participant);
        d.participant_number = earliest.participant_number;
        d.latin_square_row = latin_square_row(earliest);
        for (const std::string& name : names) d.values.push_back(joined_values(list, name));
        out.push_back(std::move(d));
    }
    return out;
}

// Whether summary.json writes the variable `name` as a number: no session records a type other
// than integer or number for it, and every value it has is a number as JSON writes one.
bool is_number_variable(const std::vector<SessionRow>& sessions, const std::string& name) {
    for (const SessionRow& s : sessions) {
        const auto type = s.variable_is_number.find(name);
        if (type != s.variable_is_number.end() && !type->second) return false;
        for (const auto& [variable, value] : s.variables)
            if (variable == name && !is_json_number(value)) return false;
    }
    return true;
}

std::string numbers_text(const std::vector<int>& numbers) {
    std::string out;
    for (int n : numbers) out += (out.empty() ? "" : ", ") + std::to_string(n);
    return out;
}

}  // namespace

StudyDay study_day(const Dataset& data) {
    StudyDay day;
    day.codes = data.codes;
    day.shared_codes = data.shared_codes;
    for (const SessionRow& s : data.sessions) {
        for (const auto& [name, value] : s.variables) add_once(day.variable_names, name);
        if (!s.notes.empty())
            day.notes.push_back({s.participant, s.session_number, s.source, s.notes});
    }
    for (const std::string& name : day.variable_names)
        day.variable_is_number.push_back(is_number_variable(data.sessions, name));
    day.participants = participant_details(data.sessions, day.variable_names);
    day.counterbalancing = counterbalancing(data.sessions);
    return day;
}

std::string participants_html(const StudyDay& day) {
    if (day.participants.empty()) return "";
    Table t;
    t.header = {"participant", "sessions", "files", "participant number", "Latin-square row"};
    t.numeric = {false, true, false, true, true};
    for (const std::string& name : day.variable_names) {
        t.header.push_back("<code>" + xml_escaped(name) + "</code>");
        t.numeric.push_back(false);
    }
    for (const ParticipantDetail& p : day.participants) {
        std::string files;
        for (const std::string& source : p.sources)
            files += (files.empty() ? "" : "<br>") + ("<code>" + xml_escaped(source) + "</code>");
        std::vector<std::string> row = {
            xml_escaped(p.participant), numbers_text(p.session_numbers), files,
            std::to_string(p.participant_number + 1),
            p.latin_square_row ? std::to_string(*p.latin_square_row + 1) : "&ndash;"};
        for (const std::string& value : p.values)
            row.push_back(value.empty() ? "<span class=\"note\">not given</span>"
                                        : text_html(value));
        t.rows.push_back(std::move(row));
    }
    std::string h = "<h3 id=\"participants\">Participants</h3>\n" + t.html();
    h += "<p class=\"note\">Sessions: each participant's session numbers (all of a participant's "
         "sessions form one cluster in the regression and one psychometric fit per scene). "
         "Participant number: their position in the whole study, from 1 "
         "(<code>study run --participant-number</code>), which picks the Latin-square row of "
         "their first session.";
    if (!day.variable_names.empty())
        h += " The other columns are the participant variables the protocol declares.";
    return h + "</p>\n";
}

std::string notes_html(const StudyDay& day) {
    std::string h = "<h3 id=\"notes\">Session notes</h3>\n";
    if (day.notes.empty())
        return h +
               "<p class=\"note\">No session has notes. (A CSV export of the trials carries none: "
               "analyse the database to see them.)</p>\n";
    Table t;
    t.header = {"participant", "session", "file", "written (UTC)", "trial", "by", "note"};
    t.numeric = {false, true, false, false, true, false, false};
    for (const SessionNotes& session : day.notes) {
        for (const NoteRow& note : session.notes) {
            t.rows.push_back(
                {xml_escaped(session.participant), std::to_string(session.session_number),
                 "<code>" + xml_escaped(session.source) + "</code>", xml_escaped(note.noted_utc),
                 note.trial_index ? std::to_string(*note.trial_index) : "&ndash;",
                 xml_escaped(note.written_by), text_html(note.text)});
        }
    }
    return h + t.html() +
           "<p class=\"note\">Trial: the 0-based trial index in its session (practice trials "
           "first) on screen when the note was written; by: the experimenter's window, "
           "<code>monoplane study note</code> (command) or the software.</p>\n";
}

std::string codes_note_html(const StudyDay& day) {
    if (day.codes == SharedCodes::PerDatabase)
        return "Each file's participant codes are its own (<code>--codes per-database</code>): "
               "every code carries its file's name as a prefix.";
    if (day.shared_codes.empty()) return "No participant code occurs in more than one file.";
    std::string shared;
    for (const std::string& code : day.shared_codes)
        shared += (shared.empty() ? "" : ", ") + xml_escaped(code);
    return "Participant codes held by more than one file (" + shared +
           ") are one person each (<code>--codes same-person</code>): their sessions from every "
           "file form one participant.";
}

std::string counterbalancing_html(const StudyDay& day) {
    const Counterbalancing& c = day.counterbalancing;
    std::string h =
        "<h3 id=\"counterbalancing\">Counterbalancing: participants per Latin-square "
        "row</h3>\n";
    if (!c.applicable)
        return h + "<p class=\"note\">Not applicable: " + xml_escaped(c.reason) + ".</p>\n";
    Table t;
    t.header = {"row", "participants"};
    t.numeric = {true, true};
    for (std::size_t row = 0; row < c.participants_per_row.size(); ++row)
        t.rows.push_back({std::to_string(row + 1), std::to_string(c.participants_per_row[row])});
    h += "<p>The scene order of each participant's first session is a row of the protocol's "
         "balanced Latin square of " +
         std::to_string(c.latin_square_rows) +
         " rows: participant number N uses row ((N &minus; 1) mod " +
         std::to_string(c.latin_square_rows) +
         ") + 1. The order is balanced over participants when every row has about as many "
         "participants as the others.</p>\n" +
         t.html();
    if (c.balanced) {
        h += "<p class=\"note\">Balanced: the rows' counts differ by at most one (" +
             std::to_string(c.participants) + " participants).</p>\n";
    } else {
        h += "<p class=\"warn\">The rows' counts differ by more than one: the scene order is not "
             "balanced over these participants, so order effects are not cancelled out. A study "
             "run on several computers or sites numbers its participants across the whole study "
             "(<code>monoplane study run --participant-number N</code>); otherwise each file "
             "starts again at row 0.</p>\n";
    }
    if (c.order_assumed)
        h += "<p class=\"note\">Some sessions come from CSV exports, which do not record the "
             "protocol's <code>first_scene</code>: they are counted as the default, "
             "latin-square.</p>\n";
    if (c.other_order > 0)
        h += "<p class=\"note\">" + std::to_string(c.other_order) +
             " participant(s) left out: their protocol orders scenes at random or as "
             "listed.</p>\n";
    return h;
}

}  // namespace monoplane::analysis::report

namespace monoplane::analysis::report {
namespace {

void counterbalancing_json(JsonWriter& json, const Counterbalancing& c) {
    json.begin_object("counterbalancing");
    json.begin_object("rows");
    for (std::size_t row = 0; row < c.participants_per_row.size(); ++row)
        json.value(std::to_string(row + 1), c.participants_per_row[row]);
    json.end_object();
    if (c.applicable) {
        json.value("balanced", c.balanced);
    } else {
        json.null("balanced");
    }
    json.value("applicable", c.applicable)
        .value("reason", c.reason)
        .value("latin_square_rows", c.latin_square_rows)
        .value("participants", c.participants)
        .value("other_order", c.other_order)
        .value("order_assumed", c.order_assumed)
        .end_object();
}

void participant_json(JsonWriter& json, const StudyDay& day, const ParticipantDetail& p) {
    json.begin_object().value("participant", p.participant);
    json.begin_array("sessions");
    for (int number : p.session_numbers) json.value("", number);
    json.end_array().begin_array("sources");
    for (const std::string& source : p.sources) json.value("", source);
    json.end_array().value("participant_number", p.participant_number + 1);
    if (p.latin_square_row) {
        json.value("latin_square_row", *p.latin_square_row + 1);
    } else {
        json.null("latin_square_row");
    }
    json.begin_object("variables");
    for (std::size_t i = 0; i < day.variable_names.size(); ++i) {
        if (p.values[i].empty()) {
            json.null(day.variable_names[i]);
        } else if (day.variable_is_number[i] && is_json_number(p.values[i])) {
            json.formatted_number(day.variable_names[i], p.values[i]);
        } else {
            json.value(day.variable_names[i], p.values[i]);
        }
    }
    json.end_object().end_object();
}

}  // namespace

void study_day_json(JsonWriter& json, const StudyDay& day) {
    json.begin_object("participant_codes").value("rule", shared_codes_name(day.codes));
    json.begin_array("shared");
    for (const std::string& code : day.shared_codes) json.value("", code);
    json.end_array().end_object();
    counterbalancing_json(json, day.counterbalancing);
    json.begin_array("participant_details");
    for (const ParticipantDetail& p : day.participants) participant_json(json, day, p);
    json.end_array();
    json.begin_array("notes");
    for (const SessionNotes& session : day.notes) {
        for (const NoteRow& note : session.notes) {
            json.begin_object()
                .value("participant", session.participant)
                .value("session", session.session_number)
                .value("source", session.source)
                .value("noted_utc", note.noted_utc);
            if (note.trial_index) {
                json.value("trial_index", *note.trial_index);
            } else {
                json.null("trial_index");
            }
            json.value("written_by", note.written_by).value("text", note.text).end_object();
        }
    }
    json.end_array();
}

}  // namespace monoplane::analysis::report
