// What the report says about the study around the trials: the participants with their sessions,
// Latin-square rows and variables, the notes written on each session, how codes shared between
// input files were joined, and whether the participants are spread evenly over the Latin
// square's rows (analysis/counterbalancing.h). Parts of report.html's "Data" and "Order effects"
// sections and of summary.json.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/counterbalancing.h"
#include "analysis/dataset.h"
#include "common/json_writer.h"

namespace monoplane::analysis::report {

struct ParticipantDetail {
    std::string participant;
    std::vector<int> session_numbers;  // ascending, each once
    std::vector<std::string> sources;  // the files their sessions came from, in reading order
    // Of the first session, both 0-based (the report and summary.json count them from 1, as
    // `study run --participant-number` does).
    int participant_number = 0;
    std::optional<int> latin_square_row;
    // One per StudyDay::variable_names; "" where not given. Sessions that disagree (one person's
    // sessions from two files, `--codes same-person`) give their values joined by " / ".
    std::vector<std::string> values;
};

struct SessionNotes {
    std::string participant;
    int session_number = 1;
    std::string source;
    std::vector<NoteRow> notes;
};

struct StudyDay {
    SharedCodes codes = SharedCodes::Refuse;  // the rule that joined the inputs' codes
    std::vector<std::string> shared_codes;    // codes held by more than one input (before prefixes)
    std::vector<std::string> variable_names;  // in the order the inputs declare them
    // One per variable_names: written to summary.json as a JSON number (protocol type integer
    // or number; from a CSV export, which does not record types, every value a number).
    std::vector<bool> variable_is_number;
    std::vector<ParticipantDetail> participants;  // by code; empty without session information
    std::vector<SessionNotes> notes;              // sessions with notes, in reading order
    Counterbalancing counterbalancing;
};

StudyDay study_day(const Dataset& data);

// HTML, every text the inputs hold escaped: the participants table (with a column per
// variable) and the notes table, for the "Data" section; "" for the parts without content.
std::string participants_html(const StudyDay& day);
std::string notes_html(const StudyDay& day);
// The counterbalancing table with a warning when the rows differ by more than one, or why there
// is none.
std::string counterbalancing_html(const StudyDay& day);
// One line for the sources table's note: how participant codes of different files were joined.
std::string codes_note_html(const StudyDay& day);

// Writes "participant_codes", "counterbalancing", "participant_details" and "notes" into an
// open JSON object (docs/analysis.md, summary.json); rows and participant numbers from 1. A
// variable of variable_is_number is a JSON number (as the value's text: every digit kept), any
// other a string, one not given null.
void study_day_json(JsonWriter& json, const StudyDay& day);

}  // namespace monoplane::analysis::report
