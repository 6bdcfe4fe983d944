// A command line as a POSIX shell reads it back: what the launcher shows under Start, to be
// copied into a terminal.
#pragma once

#include <string>
#include <vector>

namespace monoplane::lab {

// `word` as one shell word: as it is when it has only characters no shell treats specially,
// else in single quotes (a ' inside as '\''). Any time.
std::string shell_quoted(const std::string& word);

// "monoplane" and `arguments`, each quoted, one space between. Any time.
std::string shell_command_line(const std::vector<std::string>& arguments);

}  // namespace monoplane::lab
