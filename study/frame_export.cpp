// The frame and head log as CSV (`study export --format frames-csv`; docs/data.md): one row per
// displayed frame of every headset session, with the same conventions as the trial export
// (TRUE/FALSE, NA, '.' as the decimal point, text cells guarded against spreadsheet formulas).
#include <string>

#include "study/export.h"

namespace monoplane::study {
namespace {

std::string optional_number_text(const std::optional<double>& value) {
    return value ? number_text(*value) : "NA";
}

std::string optional_count(const std::optional<std::int64_t>& value) {
    return value ? std::to_string(*value) : "NA";
}

}  // namespace

const std::vector<std::string_view>& frame_export_columns() {
    static const std::vector<std::string_view> columns = {
        "participant",     "session",   "frame",   "trial_index", "shown",      "display_time_s",
        "cpu_ms",          "gpu_ms",    "missed",  "head_x",      "head_y",     "head_z",
        "head_qw",         "head_qx",   "head_qy", "head_qz",     "mono_plane", "pipelines_created",
        "driver_compiles", "session_id"};
    return columns;
}

void write_frames_csv(const ExportData& data, std::ostream& out) {
    std::string header;
    for (std::string_view column : frame_export_columns()) {
        if (!header.empty()) header += ',';
        header += column;
    }
    out << header << '\n';
    for (const auto& [session_id, frames] : data.frames) {
        const SessionInfo& session = data.sessions.at(session_id);
        // `session` is the participant's session number, as in the trials export; the
        // database's session id comes last.
        const std::string identity =
            csv_text(session.participant_code) + ',' + std::to_string(session.session_number) + ',';
        for (const FrameRecord& f : frames) {
            std::string line = identity + std::to_string(f.frame) + ',';
            line += (f.trial_index ? std::to_string(*f.trial_index) : "NA") + ',';
            line += csv_text(f.shown) + ',';
            line += seconds_text(f.display_time_ns) + ',';
            line += number_text(f.cpu_ms) + ',' + optional_number_text(f.gpu_ms) + ',';
            line += f.missed ? "TRUE" : "FALSE";
            for (std::size_t i = 0; i < 7; ++i) {
                line += ',' + (f.head ? number_text((*f.head)[i]) : std::string("NA"));
            }
            line += ',' + optional_number_text(f.mono_plane);
            line += ',' + optional_count(f.pipelines_created);
            line += ',' + optional_count(f.driver_compiles);
            line += ',' + std::to_string(session_id);
            out << line << '\n';
        }
    }
}

}  // namespace monoplane::study
