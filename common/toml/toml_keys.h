// Reading the keys of a TOML table with located, key-first error messages ("key 'left.tan_up':
// ..."), shared by HMD profiles and study protocols so both report problems the same way.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "common/toml/toml_problems.h"

namespace monoplane {

// A table being read and its name in messages: "" for the document's root, "left" for [left].
struct TomlScope {
    const toml::table& table;
    std::string name;

    std::string qualified(std::string_view key) const {
        return name.empty() ? std::string(key) : name + "." + std::string(key);
    }
};

// "key 'K': ": every message starts with the key, so a user finds it even where a line is shared.
std::string toml_key_prefix(std::string_view qualified_key);

// Unknown keys are refused rather than ignored: a misspelt key would otherwise leave the real one
// missing at best, or silently keep a default at worst. Suggests the closest known key.
void report_unknown_keys(const TomlScope& scope, std::span<const std::string_view> known,
                         TomlProblems& problems);

// The key's node, or nullptr after reporting it missing ("expected" describes the value). A key
// missing from a table is reported at the table's header; one missing from the root gets no line,
// since the root's region is line 1, which would point at whatever happens to be there.
const toml::node* find_required(const TomlScope& scope, std::string_view key,
                                std::string_view expected, TomlProblems& problems);

// "key 'K': must be <expected>, but is <the node's type>".
void report_wrong_type(const toml::node& node, std::string_view qualified_key,
                       std::string_view expected, TomlProblems& problems);

// A real number, integers accepted (`far = 1000` means 1000.0); else reports the wrong type
// ("expected" describes the value) and returns nothing.
std::optional<double> read_number(const toml::node& node, std::string_view qualified_key,
                                  std::string_view expected, TomlProblems& problems);

// An integer in [low, high]; else reports the wrong type or "N is outside the allowed range
// low..high" and returns nothing.
std::optional<std::int64_t> read_integer_in(const toml::node& node, std::string_view qualified_key,
                                            std::int64_t low, std::int64_t high,
                                            TomlProblems& problems);

}  // namespace monoplane
