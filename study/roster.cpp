#include "study/roster.h"

#include <algorithm>

namespace monoplane::study {

std::string RosterEntry::state() const {
    if (holder) return "running (" + holder->describe() + ")";
    if (row.abandoned_reason) return "abandoned (" + *row.abandoned_reason + ")";
    if (row.status == SessionStatus::Running || row.status == SessionStatus::Paused)
        return "interrupted";
    return std::string(session_status_name(row.status));
}

Result<std::vector<RosterEntry>> read_roster(const StudyStore& store) {
    Result<std::vector<RosterRow>> roster = store.roster();
    MONOPLANE_TRY(roster);
    std::vector<RosterRow> rows = std::move(roster).value();
    std::ranges::sort(rows, {}, [](const RosterRow& r) {
        return std::pair(r.participant_code, r.session_number);
    });
    std::vector<RosterEntry> entries;
    for (RosterRow& row : rows) {
        RosterEntry entry{store.path(), std::move(row), std::nullopt};
        if (entry.row.status == SessionStatus::Running ||
            entry.row.status == SessionStatus::Paused) {
            Result<std::optional<SessionHolder>> holder =
                SessionHold::holder(store.path(), entry.row.session_id);
            MONOPLANE_TRY(holder);
            entry.holder = *holder;
        }
        entries.push_back(std::move(entry));
    }
    return entries;
}

Result<std::vector<RosterEntry>> read_roster(const std::vector<std::filesystem::path>& databases) {
    std::vector<RosterEntry> entries;
    for (const std::filesystem::path& database : databases) {
        Result<std::unique_ptr<StudyStore>> store = StudyStore::open_read_only(database);
        MONOPLANE_TRY(store);
        Result<std::vector<RosterEntry>> one = read_roster(**store);
        MONOPLANE_TRY(one);
        for (RosterEntry& entry : one.value()) entries.push_back(std::move(entry));
    }
    return entries;
}

}  // namespace monoplane::study
