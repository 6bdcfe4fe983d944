// What `monoplane lab` remembers between launches: the last study database and protocols folder,
// in $XDG_CONFIG_HOME/monoplane/lab.toml (~/.config/monoplane/lab.toml without it).
#pragma once

#include <filesystem>

#include "common/result.h"

namespace monoplane::lab {

struct LabConfig {
    std::filesystem::path db;         // empty: none remembered
    std::filesystem::path protocols;  // empty: none remembered
};

// The file: $XDG_CONFIG_HOME/monoplane/lab.toml, else $HOME/.config/monoplane/lab.toml; empty
// when neither variable is set. Any time.
std::filesystem::path lab_config_file();

// The remembered settings; an absent file is none remembered, an unreadable or malformed one an
// error naming it. Any time.
Result<LabConfig> read_lab_config(const std::filesystem::path& file);

// Writes `config` (absolute paths), making the folder. Any time.
Result<void> write_lab_config(const std::filesystem::path& file, const LabConfig& config);

}  // namespace monoplane::lab
