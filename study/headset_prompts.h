// The headset's own words around a protocol's pages and questionnaire: the footer under a page
// ("Page 2 of 3 - CONFIRM: next, SWITCH: back"), a break's countdown, the questionnaire's
// header, scale and hint, the pause notice. English by default; a protocol in another language
// gives them in [text.prompts] (docs/protocols.md, "Languages"), so that a participant reads no
// word of English. Each prompt is a template whose {placeholders} the headset fills in.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace monoplane::study {

struct HeadsetPrompts {
    std::string page = "Page {page} of {pages}";       // instructions, before the action
    std::string next = "CONFIRM: next";                // instructions, not the last page
    std::string last = "CONFIRM: begin";               // instructions, the last page
    std::string back = "SWITCH: back";                 // instructions, after the first page
    std::string begin = "Press CONFIRM to begin";      // one instruction page; the ready page
    std::string resume = "Press CONFIRM to continue";  // a break whose countdown has run out
    std::string countdown = "Break: {time}";           // a break's countdown ("0:23")
    std::string question = "Question {question} of {questions}";  // the questionnaire
    std::string scale = "1 = disagree ... {points} = agree";
    std::string answer = "trigger: next value    confirm button: choose";
    std::string paused = "Paused";  // over a trial the experimenter paused

    bool operator==(const HeadsetPrompts&) const = default;
};

// One prompt as [text.prompts] names it: its key, where it is kept, and the placeholders it may
// use. "continue" is kept in `resume` and "break" in `countdown` (C++ keywords).
struct PromptKey {
    std::string_view key;
    std::string HeadsetPrompts::*member;
    std::span<const std::string_view> placeholders;
};

// Every prompt, in the order docs/protocols.md lists them. Any time.
std::span<const PromptKey> prompt_keys();

// `prompt` with each {name} replaced by its value; a placeholder without a value is left as
// written (the parser refuses unknown ones). Any time.
std::string fill_prompt(std::string_view prompt,
                        std::span<const std::pair<std::string_view, std::string>> values);

// The first {placeholder} of `prompt` that is not among `allowed`, or an unmatched brace, as a
// problem ("uses {seite}; this prompt knows {page}, {pages}"); none when it is well formed.
// Any time.
std::optional<std::string> prompt_placeholder_problem(std::string_view prompt,
                                                      std::span<const std::string_view> allowed);

}  // namespace monoplane::study
