#include "renderer/plan/frame_plan.h"

#include <array>
#include <stdexcept>

#include "renderer/plan/name_table.h"

namespace monoplane::modes {
namespace {

constexpr std::array<const char*, 2> kEyes = {"left", "right"};

constexpr NameTable<PassKind> kPassKindNames = {{PassKind::kCulling, "culling"},
                                                {PassKind::kShadow, "shadow"},
                                                {PassKind::kForward, "forward"},
                                                {PassKind::kDepthPyramid, "depth_pyramid"},
                                                {PassKind::kOcclusionCulling, "occlusion_culling"},
                                                {PassKind::kMonoSsao, "mono_ssao"},
                                                {PassKind::kComposite, "composite"},
                                                {PassKind::kSsao, "ssao"},
                                                {PassKind::kTaa, "taa"},
                                                {PassKind::kTonemap, "tonemap"},
                                                {PassKind::kDepthHistogram, "depth_histogram"},
                                                {PassKind::kReadback, "readback"}};
constexpr NameTable<GpuPredicate> kPredicateNames = {
    {GpuPredicate::kAlways, "always"},
    {GpuPredicate::kMonoAny, "mono-any"},
    {GpuPredicate::kMonoNone, "mono-none"},
    {GpuPredicate::kMonoDepthTested, "mono-depth-tested"}};
constexpr NameTable<DrawStep> kDrawStepNames = {
    {DrawStep::kMaskHidden, "mask-hidden"},
    {DrawStep::kDepthPrepass, "depth-prepass"},
    {DrawStep::kChunks, "chunks"},
    {DrawStep::kChunksShowRouting, "chunks-show-routing"},
    {DrawStep::kSky, "sky"}};

std::string resource(const std::string& view, const char* image) {
    return view + "." + image;
}

// What shapes this frame's passes, derived once from the inputs (the renderer's own rules).
struct FrameShape {
    bool hybrid = false;    // a hybrid mode, whether or not this frame draws C
    bool use_mono = false;  // C is drawn: a hybrid mode and something lies beyond m - eps
    bool farfield = false;
    bool depth_tested = false;      // the merged depth pyramid saves C's work
    bool occlusion_culled = false;  // ... and C's hidden chunks are not drawn
    bool predicated = false;
    bool single_pass = false;
    bool taa = false;
};

FrameShape shape_of(const PlanOptions& options, const PlanFrame& frame, const PlanDevice& device) {
    FrameShape s;
    s.hybrid = options.mode != Mode::kStereo;
    s.use_mono = s.hybrid && !frame.mono_skipped;
    s.farfield = s.use_mono && options.mode == Mode::kHybridFarfield;
    // monoplane's hybrid only (the far field's offset copy is another mapping), and never in the
    // debug view that shows C's whole image.
    s.depth_tested = s.use_mono && !s.farfield && frame.mono_culling != MonoCulling::kNoOpt &&
                     frame.debug != DebugView::kMonoOnly;
    s.occlusion_culled = s.depth_tested && frame.mono_culling == MonoCulling::kOcclusionCull;
    s.predicated = device.conditional_rendering;
    s.single_pass = options.stereo_pass != StereoPass::kTwoPasses;
    s.taa = options.anti_aliasing == AntiAliasing::kTaa;
    return s;
}

class PlanBuilder {
  public:
    PlanBuilder(const PlanOptions& options, const PlanFrame& frame, const FrameShape& shape)
        : options_(options), frame_(frame), s_(shape) {}

    FramePlan build() {
        add_culling();
        add_shadow();
        add_eye_forward();
        if (s_.hybrid) add_mono_passes();
        add_post_processing();
        if (options_.depth_histogram) add_depth_histogram();
        add_readback();
        return std::move(plan_);
    }

  private:
    GpuPredicate when(GpuPredicate predicate) const {
        return s_.predicated ? predicate : GpuPredicate::kAlways;
    }

    PlannedPass& add(PassKind kind, std::string name, std::string view = {}) {
        PlannedPass pass;
        pass.kind = kind;
        pass.name = std::move(name);
        pass.view = std::move(view);
        plan_.passes.push_back(std::move(pass));
        return plan_.passes.back();
    }

    // The chunk step of a forward pass: shaded, or coloured by routing in that debug view.
    DrawStep chunk_step() const {
        return frame_.debug == DebugView::kRouting ? DrawStep::kChunksShowRouting
                                                   : DrawStep::kChunks;
    }

    void add_forward_writes(PlannedPass& pass, const std::string& view) const {
        for (const char* image : {"hdr", "depth", "linear_depth"}) {
            pass.writes.push_back(resource(view, image));
        }
        if (s_.taa) pass.writes.push_back(resource(view, "velocity"));
    }

    void add_culling() {
        PlannedPass& pass = add(PassKind::kCulling, "culling");
        pass.writes = {"draw_lists", "predicates"};
    }

    void add_shadow() {
        PlannedPass& pass = add(PassKind::kShadow, "shadow");
        pass.writes = {"shadow_map"};
        if (!frame_.shadow_needed) {
            pass.skipped = "light region unchanged: the shadow map is reused";
        }
    }

    // The eyes draw their own sky in stereo, and in hybrid only when C has nothing to draw
    // (which only the GPU knows; without predicates C always draws the sky).
    std::vector<PlannedDraw> eye_draws() const {
        std::vector<PlannedDraw> draws;
        if (options_.depth_prepass) draws.push_back({DrawStep::kDepthPrepass});
        draws.push_back({chunk_step()});
        if (!s_.use_mono) {
            draws.push_back({DrawStep::kSky});
        } else if (s_.predicated) {
            draws.push_back({DrawStep::kSky, GpuPredicate::kMonoNone});
        }
        return draws;
    }

    void add_eye_forward() {
        if (s_.single_pass) {
            PlannedPass& pass = add(PassKind::kForward, "eyes.forward", "eyes");
            pass.statistics_scope = "eyes";
            pass.reads = {"draw_lists", "shadow_map"};
            for (const char* eye : kEyes) add_forward_writes(pass, eye);
            pass.draws = eye_draws();
            return;
        }
        for (const char* eye : kEyes) {
            PlannedPass& pass = add(PassKind::kForward, std::string(eye) + ".forward", eye);
            pass.statistics_scope = eye;
            pass.reads = {"draw_lists", "shadow_map"};
            add_forward_writes(pass, eye);
            pass.draws = eye_draws();
        }
    }

    std::vector<PlannedDraw> mono_draws() const {
        std::vector<PlannedDraw> draws;
        const DrawStep chunks = chunk_step();
        if (s_.depth_tested) {
            // Pixels hidden in both eyes get the nearest depth first; early depth testing then
            // rejects every fragment there. No pyramid (no eye drew anything): nothing to mask.
            draws.push_back({DrawStep::kMaskHidden, when(GpuPredicate::kMonoDepthTested)});
        }
        if (options_.depth_prepass) draws.push_back({DrawStep::kDepthPrepass});
        draws.push_back({chunks});
        draws.push_back({DrawStep::kSky, when(GpuPredicate::kMonoAny)});
        return draws;
    }

    void add_mono_passes() {
        const std::optional<std::string> no_mono =
            s_.use_mono
                ? std::nullopt
                : std::optional<std::string>("m >= far: nothing lies beyond the mono plane, no C");
        {
            PlannedPass& pass = add(PassKind::kDepthPyramid, "depth_pyramid");
            pass.reads = {"left.depth", "right.depth"};
            pass.writes = {"merged_depth"};
            pass.when = when(GpuPredicate::kMonoDepthTested);
            pass.skipped = no_mono ? no_mono : pyramid_skip_reason();
        }
        {
            PlannedPass& pass = add(PassKind::kOcclusionCulling, "occlusion_culling");
            pass.reads = {"merged_depth", "draw_lists"};
            pass.writes = {"draw_lists"};
            pass.when = when(GpuPredicate::kMonoDepthTested);
            pass.skipped = no_mono ? no_mono : occlusion_skip_reason();
        }
        {
            PlannedPass& pass = add(PassKind::kForward, "mono.forward", "mono");
            pass.statistics_scope = "mono";
            pass.reads = {"draw_lists", "shadow_map"};
            if (s_.depth_tested) pass.reads.emplace_back("merged_depth");
            add_forward_writes(pass, "mono");
            pass.draws = mono_draws();
            pass.skipped = no_mono;
        }
        if (options_.ssao) {
            // The far region's AO, computed once for both eyes (C alone sees it).
            PlannedPass& pass = add(PassKind::kMonoSsao, "mono.ssao", "mono");
            pass.reads = {"mono.linear_depth"};
            pass.writes = {"mono.ao", "mono.hdr"};
            pass.when = when(GpuPredicate::kMonoAny);
            pass.skipped = no_mono;
        }
        for (const char* eye : kEyes) {
            PlannedPass& pass = add(PassKind::kComposite, std::string(eye) + ".composite", eye);
            pass.statistics_scope = std::string(eye) + ".composite";
            pass.reads = {"mono.hdr", "mono.linear_depth", resource(eye, "depth")};
            if (s_.taa) pass.reads.emplace_back("mono.velocity");
            pass.writes = {resource(eye, "hdr"), resource(eye, "linear_depth")};
            if (s_.taa) pass.writes.push_back(resource(eye, "velocity"));
            pass.when = when(GpuPredicate::kMonoAny);
            pass.skipped = no_mono;
        }
    }

    std::optional<std::string> pyramid_skip_reason() const {
        if (s_.farfield) return "hybrid-farfield: C is frustum-culled only";
        if (frame_.debug == DebugView::kMonoOnly) return "debug view mono-only: C's whole image";
        if (frame_.mono_culling == MonoCulling::kNoOpt) return "variant no-opt: no depth test";
        return std::nullopt;
    }

    std::optional<std::string> occlusion_skip_reason() const {
        if (auto reason = pyramid_skip_reason()) return reason;
        if (!s_.occlusion_culled) return "variant discard: C's hidden chunks are still drawn";
        return std::nullopt;
    }

    void add_post_processing() {
        if (options_.ssao) {
            PlannedPass& pass = add(PassKind::kSsao, "ssao");
            for (const char* eye : kEyes) {
                pass.reads.push_back(resource(eye, "linear_depth"));
                // In hybrid the far region already carries C's AO: the eye's depth tells which.
                if (s_.use_mono) pass.reads.push_back(resource(eye, "depth"));
                pass.writes.push_back(resource(eye, "ao"));
                pass.writes.push_back(resource(eye, "hdr"));
            }
        }
        for (const char* eye : kEyes) {
            if (s_.taa) {
                PlannedPass& pass = add(PassKind::kTaa, std::string(eye) + ".taa", eye);
                pass.reads = {resource(eye, "hdr"), resource(eye, "velocity"),
                              resource(eye, "linear_depth"), resource(eye, "history")};
                pass.writes = {resource(eye, "history")};
            }
            PlannedPass& pass = add(PassKind::kTonemap, std::string(eye) + ".tonemap", eye);
            pass.reads = {resource(eye, s_.taa ? "history" : "hdr")};
            pass.writes = {resource(eye, "display")};
        }
        if (s_.hybrid) {
            // C's own tone-mapped image exists only to be looked at (mono.png).
            PlannedPass& pass = add(PassKind::kTonemap, "mono.tonemap", "mono");
            pass.reads = {"mono.hdr"};
            pass.writes = {"mono.display"};
            if (!s_.use_mono) {
                pass.skipped = "m >= far: nothing lies beyond the mono plane, no C";
            } else if (!options_.read_back) {
                pass.skipped = "no read-back: C's own image is only looked at";
            }
        }
    }

    // The eyes' final depth (C's where it shows through), counted for `--mono-plane auto`.
    void add_depth_histogram() {
        PlannedPass& pass = add(PassKind::kDepthHistogram, "depth_histogram");
        for (const char* eye : kEyes) pass.reads.push_back(resource(eye, "linear_depth"));
        pass.writes = {"depth_histogram"};
    }

    void add_readback() {
        PlannedPass& pass = add(PassKind::kReadback, "readback");
        pass.reads = {"predicates"};  // the culling counts, always
        for (const char* eye : kEyes) {
            if (options_.read_back) pass.reads.push_back(resource(eye, "display"));
            if (options_.read_back_depth) pass.reads.push_back(resource(eye, "linear_depth"));
            if (options_.read_back_ao) pass.reads.push_back(resource(eye, "ao"));
        }
        if (s_.use_mono && options_.read_back) pass.reads.emplace_back("mono.display");
        if (options_.read_back_draw_lists) pass.reads.emplace_back("draw_lists");
        pass.writes = {"host"};
    }

    const PlanOptions& options_;
    const PlanFrame& frame_;
    const FrameShape& s_;
    FramePlan plan_;
};

}  // namespace

std::string pass_kind_name(PassKind kind) {
    return name_of(kPassKindNames, kind);
}

std::string gpu_predicate_name(GpuPredicate predicate) {
    return name_of(kPredicateNames, predicate);
}

std::string draw_step_name(DrawStep step) {
    return name_of(kDrawStepNames, step);
}

std::vector<const PlannedPass*> FramePlan::executed() const {
    std::vector<const PlannedPass*> result;
    for (const PlannedPass& pass : passes) {
        if (!pass.skipped) result.push_back(&pass);
    }
    return result;
}

std::vector<std::string> FramePlan::executed_names() const {
    std::vector<std::string> names;
    for (const PlannedPass* pass : executed()) names.push_back(pass->name);
    return names;
}

const PlannedPass* FramePlan::find(const std::string& name) const {
    for (const PlannedPass& pass : passes) {
        if (pass.name == name) return &pass;
    }
    return nullptr;
}

FramePlan plan_frame(const PlanOptions& options, const PlanFrame& frame, const PlanDevice& device) {
    if (frame.mono_culling == MonoCulling::kAuto) {
        throw std::invalid_argument("plan_frame: resolve MonoCulling::kAuto to a variant first");
    }
    const FrameShape shape = shape_of(options, frame, device);
    return PlanBuilder(options, frame, shape).build();
}

}  // namespace monoplane::modes
