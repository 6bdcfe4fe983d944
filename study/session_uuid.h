// Every session's globally unique id (`session_uuid`, in the database and the exports), so the
// same session found in two files (a copy, a backup beside the original, a file given twice) is
// counted once. RFC 9562 forms: new sessions get a random one (version 4); sessions written
// before the database had the column get one derived from what identifies them (version 8, the
// RFC's form for such ids), so every copy of a file and every reading of it agree.
#pragma once

#include <string>
#include <string_view>

namespace monoplane::study {

// A random version-4 UUID in lowercase 8-4-4-4-12 form. Any time.
std::string random_session_uuid();

// A version-8 UUID from the first 122 bits of SHA-256(`identity`): the same identity always
// gives the same id. Any time.
std::string derived_session_uuid(std::string_view identity);

// True for the lowercase 8-4-4-4-12 form both functions above give.
bool is_session_uuid(std::string_view text);

}  // namespace monoplane::study
