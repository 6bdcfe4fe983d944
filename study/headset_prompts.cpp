#include "study/headset_prompts.h"

#include <algorithm>
#include <array>

namespace monoplane::study {
namespace {

constexpr std::array<std::string_view, 2> kPagePlaceholders = {"page", "pages"};
constexpr std::array<std::string_view, 1> kTimePlaceholders = {"time"};
constexpr std::array<std::string_view, 2> kQuestionPlaceholders = {"question", "questions"};
constexpr std::array<std::string_view, 1> kScalePlaceholders = {"points"};

const std::array<PromptKey, 11> kPromptKeys = {{
    {"page", &HeadsetPrompts::page, kPagePlaceholders},
    {"next", &HeadsetPrompts::next, {}},
    {"last", &HeadsetPrompts::last, {}},
    {"back", &HeadsetPrompts::back, {}},
    {"begin", &HeadsetPrompts::begin, {}},
    {"continue", &HeadsetPrompts::resume, {}},
    {"break", &HeadsetPrompts::countdown, kTimePlaceholders},
    {"question", &HeadsetPrompts::question, kQuestionPlaceholders},
    {"scale", &HeadsetPrompts::scale, kScalePlaceholders},
    {"answer", &HeadsetPrompts::answer, {}},
    {"paused", &HeadsetPrompts::paused, {}},
}};

std::string braced_list(std::span<const std::string_view> names) {
    std::string list;
    for (std::string_view name : names)
        list += (list.empty() ? "{" : ", {") + std::string(name) + "}";
    return list;
}

}  // namespace

std::span<const PromptKey> prompt_keys() {
    return kPromptKeys;
}

std::string fill_prompt(std::string_view prompt,
                        std::span<const std::pair<std::string_view, std::string>> values) {
    std::string out;
    std::size_t at = 0;
    while (at < prompt.size()) {
        const std::size_t open = prompt.find('{', at);
        const std::size_t close =
            open == std::string_view::npos ? open : prompt.find('}', open + 1);
        if (close == std::string_view::npos) break;
        out += prompt.substr(at, open - at);
        const std::string_view name = prompt.substr(open + 1, close - open - 1);
        const auto value = std::find_if(values.begin(), values.end(),
                                        [&](const auto& v) { return v.first == name; });
        out += value == values.end() ? std::string(prompt.substr(open, close - open + 1))
                                     : value->second;
        at = close + 1;
    }
    if (at < prompt.size()) out += prompt.substr(at);
    return out;
}

std::optional<std::string> prompt_placeholder_problem(std::string_view prompt,
                                                      std::span<const std::string_view> allowed) {
    const std::string known = allowed.empty() ? "this prompt has no placeholders"
                                              : "this prompt knows " + braced_list(allowed);
    for (std::size_t at = 0; at < prompt.size(); ++at) {
        if (prompt[at] == '}') return "has a '}' without its '{'; " + known;
        if (prompt[at] != '{') continue;
        const std::size_t close = prompt.find_first_of("{}", at + 1);
        if (close == std::string_view::npos || prompt[close] == '{')
            return "has a '{' without its '}'; " + known;
        const std::string_view name = prompt.substr(at + 1, close - at - 1);
        if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
            return "uses {" + std::string(name) + "}; " + known;
        at = close;
    }
    return std::nullopt;
}

}  // namespace monoplane::study
