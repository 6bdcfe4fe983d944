// Private to the study store: how values without a column type of their own are spelled in the
// database. Stored in files: never change a spelling (docs/data.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace monoplane::study {

// 64-bit unsigned values are stored as text (SQLite integers are signed): the seed in decimal
// as the user types it, the protocol hash in 16 hex digits (without the export's "fnv1a64:").
std::string stored_hash_text(std::uint64_t hash);
// `text` as a number in `base`, all of it; none for anything else (an empty text included).
std::optional<std::uint64_t> parse_stored_u64(std::string_view text, int base);

// A session's block order in one column: the scene names joined by commas (a scene's name never
// holds one: validate_schedule refuses it), and split again.
std::string join_scenes(const std::vector<std::string>& scenes);
std::vector<std::string> split_scenes(const std::string& text);

}  // namespace monoplane::study
