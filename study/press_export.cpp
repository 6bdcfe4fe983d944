// `study export --format presses-csv`: every press of the participant's controller and keys
// (table presses, schema 9) with its source, one row each, for checking how a session was
// answered (docs/data.md, "Presses").
#include <ostream>

#include "study/export.h"

namespace monoplane::study {

const std::vector<std::string_view>& presses_export_columns() {
    static const std::vector<std::string_view> columns = {
        "participant", "session", "trial", "screen", "source", "action", "key", "time_ns"};
    return columns;
}

Result<ExportData> collect_presses(const StudyStore& store) {
    Result<ExportData> sessions = collect_sessions(store);
    MONOPLANE_TRY(sessions);
    ExportData data = std::move(sessions).value();
    for (const auto& [id, session] : data.sessions) {
        Result<std::vector<ResponsePress>> presses = store.presses(id);
        MONOPLANE_TRY(presses);
        data.presses.emplace(id, std::move(presses).value());
    }
    return data;
}

void write_presses_csv(const ExportData& data, std::ostream& out) {
    std::string line;
    out << csv_header(presses_export_columns()) << '\n';
    for (const auto& [id, presses] : data.presses) {
        const auto session = data.sessions.find(id);
        if (session == data.sessions.end()) continue;
        for (const ResponsePress& press : presses) {
            line = csv_text(session->second.participant_code) + ',' +
                   std::to_string(session->second.session_number) + ',';
            line += (press.trial_index >= 0 ? std::to_string(press.trial_index) : "NA") + ',';
            line += csv_text(press.screen) + ',' + csv_text(press_source_name(press.source)) + ',';
            line += csv_text(press_action_name(press.action)) + ',';
            // NA: the controller's buttons have no key name.
            line += (press.key.empty() ? "NA" : csv_text(press.key)) + ',';
            line += std::to_string(press.time_ns);
            out << line << '\n';
        }
    }
}

}  // namespace monoplane::study
