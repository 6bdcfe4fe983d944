// Private to the study store: the schema as a list of migrations in code (docs/data.md).
// migrations()[v] takes a database from user_version v to v + 1; a new schema version appends a
// step and never edits an old one, so every database ever written can be brought forward.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace monoplane::study {

// PRAGMA application_id of monoplane study databases ("MPST"): tells ours from another
// program's SQLite file before anything is written to it.
inline constexpr std::int32_t kStoreApplicationId = 0x4D505354;

// One SQL script per step; the store runs each in the migration's transaction and then sets
// user_version itself.
std::span<const std::string_view> store_migrations();

}  // namespace monoplane::study
