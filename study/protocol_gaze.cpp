#include "study/protocol_gaze.h"

#include <array>
#include <string_view>

namespace monoplane::study {
namespace {

constexpr std::array<std::string_view, 1> kGazeKeys = {"record"};

}  // namespace

void read_gaze(const TomlScope& root, GazeSettings& gaze, TomlProblems& problems) {
    const toml::node* node = root.table.get("gaze");
    if (node == nullptr) return;
    const toml::table* table = node->as_table();
    if (table == nullptr) {
        report_wrong_type(*node, "gaze", "a table ([gaze] with record)", problems);
        return;
    }
    const TomlScope scope{*table, "gaze"};
    report_unknown_keys(scope, kGazeKeys, problems);
    if (const toml::node* record = table->get("record")) {
        if (const auto* flag = record->as_boolean()) {
            gaze.record = flag->get();
        } else {
            report_wrong_type(*record, "gaze.record", "a boolean (true or false)", problems);
        }
    }
}

std::string describe_gaze(const GazeSettings& gaze) {
    if (!gaze.record) return "not recorded";
    return "recorded per frame where the headset's runtime offers XR_EXT_eye_gaze_interaction "
           "and tracks the eyes (otherwise the session says so and records none)";
}

}  // namespace monoplane::study
