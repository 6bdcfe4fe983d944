// What the report says about where its sessions came from beyond the files: the protocol
// versions they ran (and whether designs that differ were pooled on request), and the sessions
// more than one file held that were counted once. A reader of the report sees that the study
// was one experiment, or exactly which versions were pooled. Part of report.html's "Data"
// section and of summary.json.
#pragma once

#include <string>
#include <vector>

#include "analysis/dataset.h"
#include "common/json_writer.h"

namespace monoplane::analysis::report {

// The sessions one build of monoplane ran (SessionRow::software_version; "unknown" for sessions
// whose input does not say).
struct SoftwareVersion {
    std::string version;
    int sessions = 0;
};

struct InputRecords {
    std::vector<ProtocolVersion> protocol_versions;  // in reading order
    bool pooled_protocols = false;  // designs that differ (or are not known) pooled on request
    std::vector<DroppedCopy> dropped_copies;
    std::vector<SoftwareVersion> software_versions;  // in order of first session read
};

// The records the checks left in `data` (protocol_versions.h, duplicate_sessions.h). Any time.
InputRecords input_records(const Dataset& data);

// HTML, every text the inputs hold escaped: the table of protocol versions with a note on how
// they were pooled ("" without versions); the table of sessions counted once ("" without any).
std::string protocol_versions_html(const InputRecords& inputs);
std::string dropped_copies_html(const InputRecords& inputs);
// The builds that ran the sessions, with how many each ("" without sessions).
std::string software_versions_html(const InputRecords& inputs);

// Writes "protocol_versions", "pooled_protocols", "dropped_duplicates" and
// "software_versions" ([{"version", "sessions"}]) into an open JSON
// object (docs/analysis.md, summary.json): a hash not recorded and a design not known are null.
void input_records_json(JsonWriter& json, const InputRecords& inputs);

}  // namespace monoplane::analysis::report
