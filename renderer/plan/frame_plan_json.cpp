#include "renderer/plan/frame_plan_json.h"

namespace monoplane::plan {

void write_plan_json(JsonWriter& j, const FramePlan& plan, std::string_view key) {
    j.begin_array(key);
    for (const PlannedPass& pass : plan.passes) {
        j.begin_object();
        j.value("pass", pass.name)
            .value("kind", pass.kind == PassKind::kUnit ? pass.unit : pass_kind_name(pass.kind))
            .value("view", view_name(pass.view));
        if (pass.skipped) {
            j.value("skipped", *pass.skipped);
        } else {
            j.null("skipped");
        }
        if (pass.when != GpuPredicate::kAlways) j.value("when", gpu_predicate_name(pass.when));
        if (pass.writes_display) j.value("writes_display", true);
        if (!pass.draws.empty()) {
            j.begin_array("draws");
            for (const PlannedDraw& draw : pass.draws) {
                const std::string step = draw_step_name(draw.step);
                j.value({}, draw.when == GpuPredicate::kAlways
                                ? step
                                : step + " if " + gpu_predicate_name(draw.when));
            }
            j.end_array();
        }
        j.end_object();
    }
    j.end_array();
}

}  // namespace monoplane::plan
