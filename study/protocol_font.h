// The font a protocol's screens are drawn with ([text] font, docs/protocols.md "Languages"):
// the headset draws each character with it, so a character the font lacks would reach the
// participant as an empty box. Checked when a protocol file is loaded (protocol check, study
// run, the launcher), not when a session's stored protocol is read back: the file was checked
// on the machine that ran the session, and reading results needs no fonts.
#pragma once

#include "common/result.h"
#include "study/protocol.h"

namespace monoplane::study {

// What the headset fills into its prompts' placeholders: page numbers, counts, a countdown.
inline constexpr std::string_view kFilledCharacters = "0123456789:";

// Checks that protocol.day.font (an absolute path) opens and draws every character of the pages
// ([[instructions]], [ready], [breaks], [end]), the questionnaire's items, the headset's prompts
// ([text.prompts], or the English ones it leaves out) and kFilledCharacters.
// Each missing character is one located problem "FILE:LINE:COL: key 'K': 'ä' (U+00E4) is not in the
// font ..." at the line where it is written; a questionnaire item that needs text shaping is
// refused too (pages are refused so when parsed). May be called on a protocol parse_protocol
// accepted.
Result<void> check_protocol_font(const Protocol& protocol);

}  // namespace monoplane::study
