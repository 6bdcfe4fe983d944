#include "app/commands/rig_error_budget.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "common/json_writer.h"
#include "common/result.h"

namespace monoplane::app {

void print_error_budget(std::ostream& out, const hmd::HmdProfile& profile,
                        const rig::RigInputs& inputs, double budget_arcmin,
                        rig::ErrorMeasure measure, double depth, bool json) {
    Result<rig::BudgetChoice> choice =
        rig::nearest_mono_plane_within(inputs, budget_arcmin, measure, depth);
    if (!choice) throw UserError(choice.error().message + " (HMD " + profile.source + ")");
    const char* measure_name = measure == rig::ErrorMeasure::kEye ? "eye" : "disparity";
    if (json) {
        JsonWriter j;
        j.begin_object();
        j.value("command", "rig").value("hmd", profile.name).value("hmd_source", profile.source);
        j.value("ipd", inputs.ipd).value("near", inputs.near).value("far", inputs.far);
        j.value("error_budget_arcmin", budget_arcmin).value("measure", measure_name);
        j.value("budget_depth", depth);  // infinity is written null: "any depth"
        j.value("mono_plane", choice->mono_plane).value("stereo", choice->stereo);
        j.value("max_error_arcmin", choice->error.eye_arcmin);
        j.value("max_disparity_error_arcmin", choice->error.disparity_arcmin);
        j.end_object();
        out << j.str() << "\n";
        return;
    }
    const std::string depth_text = std::isinf(depth)
                                       ? "content at any depth"
                                       : "content up to " + std::to_string(depth) + " m";
    char line[400];
    if (choice->stereo) {
        std::snprintf(line, sizeof line,
                      "no mono plane before the far plane (%g m) keeps the %s error within %g "
                      "arcmin for %s: render stereo\n",
                      inputs.far, measure_name, budget_arcmin, depth_text.c_str());
    } else {
        std::snprintf(line, sizeof line,
                      "nearest mono plane within %g arcmin (%s error, %s): m = %.6g m\n"
                      "  there: each eye %.4f arcmin, disparity %.4f arcmin\n",
                      budget_arcmin, measure_name, depth_text.c_str(), choice->mono_plane,
                      choice->error.eye_arcmin, choice->error.disparity_arcmin);
    }
    out << line;
}

}  // namespace monoplane::app
