// The specification of a psychometric simulated observer (issue 21):
// `psychometric:threshold=T,slope=B,lapse=L`, the observer that chooses the reference with the
// probability study/psychometric.h gives at the trial's m. Its known threshold is what the
// staircase validation (`simulate`) compares estimates with.
#pragma once

#include <string_view>

#include "common/result.h"
#include "study/psychometric.h"

namespace monoplane::study {

// "psychometric:": an observer name with this prefix is a specification.
inline constexpr std::string_view kPsychometricPrefix = "psychometric:";

// Parses the part after the prefix or the whole name: comma-separated key=value pairs,
// threshold (metres, > 0) and slope (> 0) required, lapse in [0, 0.5) optional (default 0).
// Errors say where (the character position in the specification) and what: a pair without '=', an
// unknown key (with "did you mean"), a value that is not a finite number or out of range, a key
// given twice, a missing required key. Any time.
Result<PsychometricFunction> parse_psychometric_spec(std::string_view spec);

// "gaze:threshold=T,slope=B,lapse=L" (issue 45, docs/gaze.md): the observer whose stimulus is
// hybrid's error where its gaze rests (arcmin), chosen as the reference with probability
// 0.5 + (0.5 - lapse) e^B / (T^B + e^B): the psychometric function of the error e, rising through
// 0.75 - lapse / 2 at e = T arcmin. Parsed as parse_psychometric_spec parses, with threshold in
// arcmin.
inline constexpr std::string_view kGazePrefix = "gaze:";
Result<PsychometricFunction> parse_gaze_spec(std::string_view spec);

}  // namespace monoplane::study
