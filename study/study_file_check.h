// What a file given as a study database is, judged from its bytes before SQLite opens it: SQLite
// would take a 0-byte file for an empty database and write a new schema into it, and would read
// a truncated copy until the first missing page. Every command asks this first, so a refused
// file is refused with one line that says what it is and what to do, and nothing is written.
#pragma once

#include <cstdint>
#include <filesystem>

#include "common/result.h"

namespace monoplane::study {

// How a command will use the database.
enum class StudyFileUse {
    Create,    // `study run`, the launcher's Create: a missing file is made
    Existing,  // `study resume`, `study note`, `study migrate`: it must exist; it is written
    Read,      // list, export, analyze, the launcher's roster: it must exist; never written
};

// What check_study_file found: whether the file exists (only Create accepts a missing one).
struct StudyFileState {
    bool exists = false;
    std::uintmax_t size_bytes = 0;
};

// Refuses, with one line naming the file: a missing file (unless `use` is Create), a directory
// or other non-regular file, a 0-byte file ("a copy that failed?"), a file that does not start
// as a SQLite database, and a SQLite file shorter than its header says (truncated). What SQLite
// must judge (another program's database, a newer schema, a corrupt page) is the store's to
// refuse. Reads at most the first 100 bytes; any time.
Result<StudyFileState> check_study_file(const std::filesystem::path& file, StudyFileUse use);

}  // namespace monoplane::study
