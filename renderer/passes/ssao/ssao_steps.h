// The steps of SSAO (renderer/passes/ssao/ssao_unit.cpp): one table that both the unit's
// declaration (what each step reads and writes) and its recorder (what each step dispatches)
// walk, so that the two cannot drift apart. Vulkan-free: the plan's half of the unit compiles it.
//
// When may this be called: any time; pure.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "renderer/graph/frame_graph.h"
#include "renderer/plan/pass_steps.h"

namespace monoplane::passes::ssao {

// What a step records (SsaoPass::dispatch and SsaoPass::apply).
enum class Dispatch {
    kEstimate,  // HBAO+ in one view alone
    kFilterX,   // the depth-aware bilateral filter, horizontally, in one view alone
    kFilterY,   // ... and vertically on that
    // papers/002 Sect. 3.1: the visibility map L of `self` by reverse reprojection into `other`
    // with a back-check.
    kStereoVisibility,
    kStereoEstimate,  // Sect. 3.1: the stereo estimate over both eyes (the left eye)
    // Sect. 3.2: the left estimate reprojected where L allows, the rest from scratch (the right)
    kStereoReprojectedEstimate,
    kStereoFilterX,  // Sect. 3.3: the stereo filter, horizontally
    kStereoFilterY,  // ... and vertically on that
    kApply,          // hdr *= AO
};

struct Step {
    std::string name;  // the plan's step name
    Dispatch dispatch;
    plan::ViewId self;   // the view the step writes (the AO of, or the HDR of for kApply)
    plan::ViewId other;  // the other eye in the stereo dispatches, else `self`
};

// C's SSAO in hybrid: "estimate", "filter-x", "filter-y" over C alone, then "apply" into C's HDR.
std::vector<Step> mono_steps();
// The eyes' SSAO: per eye ("left.estimate", "left.filter-x", "left.filter-y", then the right
// eye's) or stereo-consistent (visibility, estimate, filter-x, filter-y, each once per eye over
// both eyes' images: "visibility-left", "visibility-right", ...), then "left.apply" and
// "right.apply".
std::vector<Step> eye_steps(bool stereo);
// The step named `name` in any of the tables above; nullptr for none.
const Step* step_named(std::string_view name);

// The steps' uses of the frame's images. A compute step reads the linear depth and rewrites the
// scratch and AO images of the views it binds (both eyes' in a stereo dispatch: each dispatch
// binds both, and a shader's storage images count as read and written wherever it could touch
// them); an apply samples the AO and blends into the HDR image, depth-tested against the eye's
// near content when `near_only` (hybrid: the far region already carries C's AO).
std::vector<graph::Step> declared_steps(plan::PlanResources& r, const std::vector<Step>& steps,
                                        bool near_only);

}  // namespace monoplane::passes::ssao
