#include "app/lab/shell_words.h"

#include <algorithm>
#include <cctype>

namespace monoplane::lab {

std::string shell_quoted(const std::string& word) {
    const bool plain = !word.empty() && std::ranges::all_of(word, [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) ||
               std::string_view("_-./=:,+@%").find(c) != std::string_view::npos;
    });
    if (plain) return word;
    std::string quoted = "'";
    for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

std::string shell_command_line(const std::vector<std::string>& arguments) {
    std::string line = "monoplane";
    for (const std::string& a : arguments) line += " " + shell_quoted(a);
    return line;
}

}  // namespace monoplane::lab
