// The one rule for programming errors: code that breaks a function's stated contract (its "when
// may this be called", a refusal its header lists as a programming error, two parts of the
// renderer that disagree) stops the program where it happened, in every build type, with the
// place and what was expected on stderr. Tests show such a refusal with a death test.
//
// Never for what a user, a file, a device or a runtime can cause: those return an error value a
// person can act on (common/result.h), and only main() turns one into an exit status.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <source_location>
#include <string_view>

namespace monoplane {

// Prints "monoplane: programming error at FILE:LINE (FUNCTION): WHAT" and aborts.
[[noreturn]] inline void programming_error(
    std::string_view what, std::source_location where = std::source_location::current()) {
    std::fprintf(stderr, "monoplane: programming error at %s:%u (%s): %.*s\n", where.file_name(),
                 static_cast<unsigned>(where.line()), where.function_name(),
                 static_cast<int>(what.size()), what.data());
    std::fflush(stderr);
    std::abort();
}

}  // namespace monoplane

// Checks a precondition or an invariant in every build type (unlike assert, which NDEBUG drops).
#define MONOPLANE_EXPECTS(condition) \
    ((condition) ? static_cast<void>(0) : ::monoplane::programming_error("expected " #condition))
