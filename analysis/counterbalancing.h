// Whether a study's participants are spread evenly over the rows of its balanced Latin square
// (the protocol's first_scene = "latin-square"): the square balances the scene order only when
// each row has about as many participants as the others. A study run on several machines or at
// several sites, each counting its participants from 0, starts the rotation again in each file;
// `study run --participant-number` numbers participants across the whole study, and this check
// shows whether that was done.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "analysis/dataset.h"

namespace monoplane::analysis {

struct Counterbalancing {
    bool applicable = false;
    std::string reason;  // why not, when !applicable
    int latin_square_rows = 0;
    std::vector<int> participants_per_row;  // by 0-based row, 0 .. latin_square_rows - 1
    bool balanced = false;                  // the row counts differ by at most one
    int participants = 0;                   // participants counted
    // Participants left out because their protocol orders scenes "random" or "fixed".
    int other_order = 0;
    // Some first sessions came from inputs that do not record how the protocol orders scenes
    // (CSV exports): counted as the default, latin-square.
    bool order_assumed = false;
};

// Each participant's first session: the lowest session number, then the earliest start, then
// the first read.
std::map<std::string, const SessionRow*> first_sessions(const std::vector<SessionRow>& sessions);

// The 0-based Latin-square row a session's block order came from (participant_number modulo the
// rows, as study/schedule.cpp picks it), or none when the session's protocol is not known to use a
// Latin square.
std::optional<int> latin_square_row(const SessionRow& session);

// Counts each participant once, in the row of their first session. Not applicable (with the
// reason) without session information, when no participant's protocol uses a Latin square, or
// when the participants' protocols have Latin squares of different sizes (other scene counts).
Counterbalancing counterbalancing(const std::vector<SessionRow>& sessions);

}  // namespace monoplane::analysis
