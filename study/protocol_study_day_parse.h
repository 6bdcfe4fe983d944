// Reading the study-day keys of a protocol (protocol_study_day.h; docs/protocols.md, "A study
// day"): sessions, repetitions, blocking, text_height_deg and the tables [[instructions]], [ready],
// [breaks], [end] and [[variables]]. Each reader records its problems and goes on, as
// protocol.cpp's do, so a user sees every mistake at once, located, with "did you mean" for
// misspelt keys and values.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "common/toml/toml_keys.h"
#include "study/protocol_staircase.h"
#include "study/protocol_study_day.h"

namespace monoplane::study {

// The study-day keys of a protocol's top level (for its list of known keys).
inline constexpr std::array<std::string_view, 10> kStudyDayKeys = {
    "sessions", "repetitions", "blocking", "text_height_deg", "instructions",
    "ready",    "breaks",      "end",      "variables",       "text"};

// Limits the readers enforce; the fuzz harness and the tests check accepted protocols against
// them.
inline constexpr int kMaxSessions = 20;
inline constexpr int kMaxRepetitions = 50;
inline constexpr std::size_t kMaxPageCharacters = 2000;
inline constexpr std::size_t kMaxInstructionPages = 50;
inline constexpr int kMaxBreakInterval = 1000;
inline constexpr double kMaxBreakSeconds = 1800.0;
inline constexpr double kMinTextHeightDeg = 0.5;
inline constexpr double kMaxTextHeightDeg = 10.0;
inline constexpr std::size_t kMaxVariables = 50;
inline constexpr std::size_t kMaxVariableHelp = 200;

// Reads the study-day keys from the protocol's root into `day` (left at its defaults where a key
// is absent). `procedure` is the protocol's (already read): staircases choose their own trials
// and interleave their scenes, so repetitions other than 1, blocking and between-block breaks are
// refused with one. Reports, located: wrong types; sessions outside 1..20, repetitions outside
// 1..50, an unknown blocking, text_height_deg outside [0.5, 10]; unknown keys in every table;
// a page without text, blank, longer than 2000 characters, not UTF-8, with a control character
// or with one that needs text shaping (text/complex_scripts.h: Arabic, Hebrew, the Indic
// scripts, combining marks; whether the font has each character is checked when the file is
// loaded, protocol_font.h); more than 50 instruction pages; [text] with a font that is not a
// non-empty absolute path;
// [breaks] with neither every_trials > 0 nor between_blocks = true, every_trials outside
// 0..1000, min_s outside [0, 1800], between_blocks with blocking = "none"; variables without a
// name or type, a name that is not [a-z][a-z0-9_]* of at most 32 characters or is declared
// twice, an unknown type, min / max on a choice or text variable (or not integers on an integer
// one), min > max, choices missing from a choice variable or given to another type, empty,
// blank or repeated choices, a help that is not one line of at most 200 characters, more than 50
// variables. Any time.
void read_study_day(const TomlScope& root, Procedure procedure, StudyDaySettings& day,
                    TomlProblems& problems);

// A break after every N data trials in a session of fewer than N + 1 data trials would never be
// shown: reported at [breaks] every_trials. `data_trials` is the session's (the most, for a
// staircase). Call after read_study_day, once the scenes and distances are known.
void check_break_interval(const TomlScope& root, const StudyDaySettings& day,
                          std::size_t data_trials, TomlProblems& problems);

}  // namespace monoplane::study
