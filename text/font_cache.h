// Fonts opened once per process: the headset draws a page, a label, a questionnaire item with
// the protocol's font, each time by path, and a FreeType face costs a file read to open.
#pragma once

#include <filesystem>
#include <memory>

#include "common/result.h"
#include "text/font.h"

namespace monoplane::text {

// The font at `path`, opened on first use and kept to the process's end. Thread-safe.
Result<std::shared_ptr<const Font>> cached_font(const std::filesystem::path& path);

}  // namespace monoplane::text
