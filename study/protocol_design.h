// What makes two protocol versions the same experiment: the design (scenes, distances,
// alternatives, procedure and its staircase, order and counterbalancing, repetitions, blocking,
// sessions, practice, the clip range and the render configuration) as opposed to its text
// (comments, instructions, questionnaire wording, breaks). A participant's later session may
// change the text freely (it is recorded); a change of design is refused unless the
// experimenter gives a reason, and `analyze` refuses to pool sessions of different designs
// unless told to (docs/protocols.md, "Changing a protocol during a study").
#pragma once

#include <string>
#include <vector>

#include "study/protocol.h"

namespace monoplane::study {

// The design fields in which `earlier` and `later` differ, each as "mono_planes: 2, 6, 12 ->
// 3, 8" (empty: the same design). Pure; any time.
std::vector<std::string> design_differences(const Protocol& earlier, const Protocol& later);

// The differences above in one line ("mono_planes: ...; repetitions: 3 -> 1").
std::string describe_differences(const std::vector<std::string>& differences);

}  // namespace monoplane::study
