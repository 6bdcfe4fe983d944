// What this build of monoplane is: its version, the git commit it was built from and its build
// type. `monoplane --version` prints it and every session records it (software_version), so a
// lab can tell which build collected which data. The definition is generated at build time by
// cmake/write_build_info.cmake.
#pragma once

#include <string>
#include <string_view>

namespace monoplane::app {

struct BuildInfo {
    std::string_view version;       // the project's version, e.g. "0.1.0"
    std::string_view git_revision;  // 12 hex digits, "-modified" appended for uncommitted
                                    // changes to tracked files; "unknown" outside a git checkout
    std::string_view build_type;    // CMAKE_BUILD_TYPE, e.g. "RelWithDebInfo"
};

// Any time.
const BuildInfo& build_info();

// "monoplane 0.1.0 (abcdef012345)": what a session records as its software_version. Any time.
std::string software_version();

// The lines `monoplane --version` prints (without the last line break): version, git revision, the
// study database schema this build writes, and the build type. Any time.
std::string version_text();

}  // namespace monoplane::app
