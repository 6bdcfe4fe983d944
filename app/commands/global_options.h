// Options every GPU command accepts.
#pragma once

#include <string>

namespace monoplane::app {

struct GlobalOptions {
    std::string device;       // --device: index or part of a name (see `monoplane devices`)
    bool validation = false;  // --validation: Khronos validation layer; any message fails
};

}  // namespace monoplane::app
