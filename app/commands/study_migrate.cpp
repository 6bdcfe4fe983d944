// `monoplane study migrate --db FILE`: brings a study database of an older schema to this
// build's, keeping the original as FILE.schema<N>.bak. The reading commands never migrate (they
// read a private copy), and run, resume and note migrate only a file they are about to write:
// this is the explicit step for a lab that wants its archive on the new schema.
#include <iostream>

#include "app/commands/study_options.h"
#include "study/study_store.h"

namespace monoplane::app {

void migrate_study(const StudyOptions& o) {
    auto store = study::StudyStore::open_existing(o.db).value_or_throw();
    const int found = store->found_schema_version();
    if (!store->schema_backup()) {
        std::cout << o.db << ": schema version " << found << ", already this build's; unchanged\n";
        return;
    }
    std::cout << o.db << ": migrated from schema version " << found << " to "
              << study::StudyStore::kSchemaVersion << "; the original is kept as "
              << store->schema_backup()->string() << "\n";
}

}  // namespace monoplane::app
