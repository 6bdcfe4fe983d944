// The frame plan (renderer/plan/frame_plan.h) against pass lists written out here by hand from the
// rules of the modes (docs/hybrid.md, "The pipeline: the frame plan"), not
// copied from plan_frame's output, and a generic check that every resource a pass reads was
// written by an earlier pass of the same frame, over every combination of options. No GPU.
//
// MONOPLANE_PRINT_PLANS=1 build/tests/unit/frame_plan_test --gtest_filter='FramePlanPrint.*'
// prints the plans docs/architecture.md shows (and the test checks the page shows them).
// prints the plans that docs/architecture.md shows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "renderer/passes/pass_unit_declarations.h"
#include "renderer/plan/frame_plan.h"
#include "renderer/plan/render_choices.h"

namespace monoplane::plan {

// gtest's printer for draws in failure messages ("sky if mono-any").
void PrintTo(const PlannedDraw& draw, std::ostream* os) {
    *os << draw_step_name(draw.step);
    if (draw.when != GpuPredicate::kAlways) *os << " if " << gpu_predicate_name(draw.when);
}

namespace {

// The frame plan as the renderer plans it: with the registered pass units (TAA among them).
using passes::plan_frame;
using Names = std::vector<std::string>;
using Draws = std::vector<PlannedDraw>;

constexpr GpuPredicate kAlways = GpuPredicate::kAlways;
constexpr GpuPredicate kMonoAny = GpuPredicate::kMonoAny;
constexpr GpuPredicate kMonoNone = GpuPredicate::kMonoNone;
constexpr GpuPredicate kMonoDepthTested = GpuPredicate::kMonoDepthTested;

const std::vector<Mode> kModes = {Mode::kStereo, Mode::kHybrid, Mode::kHybridFarfield};
const std::vector<Mode> kHybridModes = {Mode::kHybrid, Mode::kHybridFarfield};
const std::vector<MonoCulling> kCullings = {MonoCulling::kNoOpt, MonoCulling::kDiscard,
                                            MonoCulling::kOcclusionCull};
const std::vector<StereoPass> kStereoPasses = {StereoPass::kTwoPasses, StereoPass::kMultiview,
                                               StereoPass::kGeometryShader, StereoPass::kInstanced};
const std::vector<StereoPass> kSinglePasses = {StereoPass::kMultiview, StereoPass::kGeometryShader,
                                               StereoPass::kInstanced};
const std::vector<AntiAliasing> kAntiAliasings = {AntiAliasing::kNone, AntiAliasing::kTaa};

// The passes of C that a frame with nothing beyond the mono plane leaves out.
const Names kMonoPasses = {"depth_pyramid",  "occlusion_culling", "mono.forward",
                           "left.composite", "right.composite",   "mono.tonemap"};

// Stereo, two passes, no AA, no SSAO, the light's region moved (the list).
const Names kStereoList = {"culling",      "shadow",        "left.forward", "right.forward",
                           "left.tonemap", "right.tonemap", "readback"};

// Hybrid, something beyond m, occlusion-cull: every pass of C runs.
const Names kHybridList = {
    "culling",           "shadow",       "left.forward",   "right.forward",   "depth_pyramid",
    "occlusion_culling", "mono.forward", "left.composite", "right.composite", "left.tonemap",
    "right.tonemap",     "mono.tonemap", "readback"};

// Without predicates C always draws, so each composite tone maps into the display image whole
// and the eyes' separate tone mappings are left out (PlannedPass::writes_display).
const Names kFusedTonemaps = {"left.tonemap", "right.tonemap"};

PlanOptions options_for(Mode mode, StereoPass stereo_pass = StereoPass::kTwoPasses) {
    PlanOptions options;
    options.mode = mode;
    options.stereo_pass = stereo_pass;
    return options;
}

PlanFrame frame_with(bool mono_skipped, MonoCulling culling = MonoCulling::kOcclusionCull) {
    PlanFrame frame;
    frame.mono_skipped = mono_skipped;
    frame.mono_culling = culling;
    return frame;
}

FramePlan plan_of(const PlanOptions& options, const PlanFrame& frame, bool conditional) {
    return plan_frame(options, frame, PlanDevice{conditional});
}

Names without(Names names, const Names& removed) {
    std::erase_if(names, [&](const std::string& name) {
        return std::find(removed.begin(), removed.end(), name) != removed.end();
    });
    return names;
}

std::ptrdiff_t index_of(const Names& names, const std::string& name) {
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? -1 : it - names.begin();
}

bool contains(const std::vector<std::string>& list, const std::string& item) {
    return std::find(list.begin(), list.end(), item) != list.end();
}

// The pass the plan shows by that name (render --json's "pass"), or nullptr.
const PlannedPass* named(const FramePlan& plan, const std::string& name) {
    for (const PlannedPass& pass : plan.passes) {
        if (pass.name == name) return &pass;
    }
    return nullptr;
}

// The draws of a pass the plan must have.
Draws draws_of(const FramePlan& plan, const std::string& name) {
    const PlannedPass* pass = named(plan, name);
    if (pass == nullptr) {
        ADD_FAILURE() << "no pass " << name;
        return {};
    }
    return pass->draws;
}

// Whether the plan has that pass and leaves it out with a reason.
bool skipped_with_reason(const FramePlan& plan, const std::string& name) {
    const PlannedPass* pass = named(plan, name);
    return pass != nullptr && pass->skipped.has_value() && !pass->skipped->empty();
}

std::string joined(const std::vector<std::string>& list) {
    std::string text;
    for (const std::string& item : list) text += (text.empty() ? "" : ", ") + item;
    return text;
}

// Two executed passes that do the same (everything but a skip reason).
void expect_same_pass(const FramePlan& pa, const PlannedPass& a, const FramePlan& pb,
                      const PlannedPass& b, const std::string& context) {
    EXPECT_EQ(a.kind, b.kind) << context << ": " << a.name;
    EXPECT_EQ(a.name, b.name) << context;
    EXPECT_EQ(a.view, b.view) << context << ": " << a.name;
    EXPECT_EQ(a.statistics_scope, b.statistics_scope) << context << ": " << a.name;
    EXPECT_EQ(pa.reads(a), pb.reads(b)) << context << ": " << a.name;
    EXPECT_EQ(pa.writes(a), pb.writes(b)) << context << ": " << a.name;
    EXPECT_EQ(a.when, b.when) << context << ": " << a.name;
    EXPECT_EQ(a.draws, b.draws) << context << ": " << a.name;
}

// A plan whose composites write the display images: what each reads and writes, when it runs,
// what becomes of the tonemap, and that nothing after a composite but its eye's tonemap reads
// the eye's HDR image.
void expect_fused(const FramePlan& plan, bool conditional, const std::string& context) {
    for (const std::string eye : {"left", "right"}) {
        const PlannedPass* composite = named(plan, eye + ".composite");
        const PlannedPass* tonemap = named(plan, eye + ".tonemap");
        ASSERT_NE(composite, nullptr) << context;
        ASSERT_NE(tonemap, nullptr) << context;
        EXPECT_FALSE(composite->skipped.has_value()) << context;
        EXPECT_TRUE(composite->writes_display) << context << " " << eye;
        EXPECT_EQ(composite->when, conditional ? kMonoAny : kAlways) << context;
        Names reads = {"mono.hdr", "mono.linear_depth", eye + ".hdr", eye + ".depth",
                       eye + ".linear_depth"};
        if (conditional) reads.emplace_back("predicates");
        EXPECT_EQ(plan.reads(*composite), reads) << context;
        EXPECT_EQ(plan.writes(*composite), (Names{eye + ".linear_depth", eye + ".display"}))
            << context;
        if (conditional) {
            EXPECT_FALSE(tonemap->skipped.has_value()) << context;
            EXPECT_EQ(tonemap->when, kMonoNone) << context;
            // It loads the display image: when the GPU skips its draw, the composite's stays.
            EXPECT_EQ(plan.reads(*tonemap), (Names{eye + ".hdr", eye + ".display", "predicates"}))
                << context;
        } else {
            EXPECT_EQ(tonemap->skipped,
                      "fused into " + eye + ".composite: nothing else reads " + eye + ".hdr")
                << context;
        }
        bool after = false;
        for (const PlannedPass* pass : plan.executed()) {
            if (after && pass != tonemap) {
                EXPECT_FALSE(contains(plan.reads(*pass), eye + ".hdr")) << context << pass->name;
                EXPECT_FALSE(contains(plan.writes(*pass), eye + ".hdr")) << context << pass->name;
            }
            after = after || pass == composite;
        }
    }
}

TEST(FramePlan, StereoTwoPassesRunsCullingShadowForwardTonemapReadback) {
    for (bool conditional : {false, true}) {
        const FramePlan plan = plan_of(options_for(Mode::kStereo), PlanFrame{}, conditional);
        EXPECT_EQ(plan.executed_names(), kStereoList);
        const Draws eye = {{DrawStep::kChunks, kAlways}, {DrawStep::kSky, kAlways}};
        EXPECT_EQ(draws_of(plan, "left.forward"), eye);
        EXPECT_EQ(draws_of(plan, "right.forward"), eye);
        ASSERT_NE(named(plan, "left.forward"), nullptr);
        EXPECT_EQ(named(plan, "left.forward")->view, ViewId::kLeft);
        EXPECT_EQ(named(plan, "right.forward")->view, ViewId::kRight);
        EXPECT_EQ(named(plan, "left.forward")->kind, PassKind::kForward);
        // Stereo has no pass of C at all, not even a skipped one.
        for (const std::string& name : kMonoPasses) EXPECT_EQ(named(plan, name), nullptr) << name;
        for (const PlannedPass* pass : plan.executed()) EXPECT_EQ(pass->when, kAlways);
    }
}

TEST(FramePlan, HybridWithNothingBeyondTheMonoPlaneRunsExactlyStereosPasses) {
    for (Mode mode : kHybridModes) {
        for (MonoCulling culling : kCullings) {
            for (bool conditional : {false, true}) {
                for (AntiAliasing aa : kAntiAliasings) {
                    for (bool ssao : {false, true}) {
                        for (bool prepass : {false, true}) {
                            for (StereoPass stereo_pass : kStereoPasses) {
                                PlanOptions hybrid = options_for(mode, stereo_pass);
                                hybrid.anti_aliasing = aa;
                                hybrid.ssao = ssao;
                                hybrid.depth_prepass = prepass;
                                PlanOptions stereo = hybrid;
                                stereo.mode = Mode::kStereo;
                                std::ostringstream context;
                                context << mode_name(mode) << " " << mono_culling_name(culling)
                                        << " conditional " << conditional << " "
                                        << anti_aliasing_name(aa) << " ssao " << ssao << " prepass "
                                        << prepass << " " << stereo_pass_name(stereo_pass);
                                const FramePlan h =
                                    plan_of(hybrid, frame_with(true, culling), conditional);
                                const FramePlan s =
                                    plan_of(stereo, frame_with(true, culling), conditional);
                                ASSERT_EQ(h.executed_names(), s.executed_names()) << context.str();
                                const auto he = h.executed();
                                const auto se = s.executed();
                                for (std::size_t i = 0; i < he.size(); ++i) {
                                    expect_same_pass(h, *he[i], s, *se[i], context.str());
                                }
                                Names skipped = kMonoPasses;
                                if (ssao) skipped.emplace_back("mono.ssao");
                                for (const std::string& name : skipped) {
                                    EXPECT_TRUE(skipped_with_reason(h, name))
                                        << context.str() << ": " << name;
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    // And the hand-written list for the plain case.
    const FramePlan plan = plan_of(options_for(Mode::kHybrid), frame_with(true), true);
    EXPECT_EQ(plan.executed_names(), kStereoList);
}

TEST(FramePlan, NothingBeyondMMinusEpsDropsCAndTheComposite) {
    for (Mode mode : kHybridModes) {
        const FramePlan plan = plan_of(options_for(mode), frame_with(true), true);
        for (const char* name : {"mono.forward", "left.composite", "right.composite"}) {
            EXPECT_TRUE(skipped_with_reason(plan, name)) << mode_name(mode) << " " << name;
        }
        for (const std::string& name : plan.executed_names()) {
            EXPECT_EQ(name.find("mono"), std::string::npos) << mode_name(mode) << " " << name;
            EXPECT_EQ(name.find("composite"), std::string::npos) << mode_name(mode) << " " << name;
        }
        // The eyes then draw their own sky, unconditionally.
        const Draws eye = {{DrawStep::kChunks, kAlways}, {DrawStep::kSky, kAlways}};
        EXPECT_EQ(draws_of(plan, "left.forward"), eye) << mode_name(mode);
        EXPECT_EQ(draws_of(plan, "right.forward"), eye) << mode_name(mode);
    }
}

TEST(FramePlan, HybridOcclusionCullWithConditionalRendering) {
    const FramePlan plan = plan_of(options_for(Mode::kHybrid), frame_with(false), true);
    EXPECT_EQ(plan.executed_names(), kHybridList);
    const Draws mono = {{DrawStep::kMaskHidden, kMonoDepthTested},
                        {DrawStep::kChunks, kAlways},
                        {DrawStep::kSky, kMonoAny}};
    EXPECT_EQ(draws_of(plan, "mono.forward"), mono);
    const Draws eye = {{DrawStep::kChunks, kAlways}, {DrawStep::kSky, kMonoNone}};
    EXPECT_EQ(draws_of(plan, "left.forward"), eye);
    EXPECT_EQ(draws_of(plan, "right.forward"), eye);
    ASSERT_NE(named(plan, "mono.forward"), nullptr);
    EXPECT_EQ(named(plan, "mono.forward")->view, ViewId::kMono);
    // C's passes wait for the GPU's verdict: the pyramid and its culling only when C has
    // something and an eye drew something, the composites only when C has something.
    EXPECT_EQ(named(plan, "depth_pyramid")->when, kMonoDepthTested);
    EXPECT_EQ(named(plan, "occlusion_culling")->when, kMonoDepthTested);
    EXPECT_EQ(named(plan, "left.composite")->when, kMonoAny);
    EXPECT_EQ(named(plan, "right.composite")->when, kMonoAny);
    EXPECT_EQ(named(plan, "left.composite")->view, ViewId::kLeft);
    EXPECT_EQ(named(plan, "right.composite")->view, ViewId::kRight);
}

TEST(FramePlan, HybridWithoutConditionalRenderingPredicatesNothingAndEyesDrawNoSky) {
    for (MonoCulling culling : kCullings) {
        const FramePlan plan =
            plan_of(options_for(Mode::kHybrid), frame_with(false, culling), false);
        for (const PlannedPass& pass : plan.passes) {
            EXPECT_EQ(pass.when, kAlways) << pass.name;
            for (const PlannedDraw& draw : pass.draws) EXPECT_EQ(draw.when, kAlways) << pass.name;
        }
        const Draws eye = {{DrawStep::kChunks, kAlways}};
        EXPECT_EQ(draws_of(plan, "left.forward"), eye) << mono_culling_name(culling);
        EXPECT_EQ(draws_of(plan, "right.forward"), eye) << mono_culling_name(culling);
    }
    const FramePlan plan = plan_of(options_for(Mode::kHybrid), frame_with(false), false);
    EXPECT_EQ(plan.executed_names(), without(kHybridList, kFusedTonemaps));
    const Draws mono = {
        {DrawStep::kMaskHidden, kAlways}, {DrawStep::kChunks, kAlways}, {DrawStep::kSky, kAlways}};
    EXPECT_EQ(draws_of(plan, "mono.forward"), mono);
}

TEST(FramePlan, DiscardBuildsThePyramidButDoesNotOcclusionCull) {
    for (bool conditional : {false, true}) {
        const FramePlan plan = plan_of(options_for(Mode::kHybrid),
                                       frame_with(false, MonoCulling::kDiscard), conditional);
        const Names fused = conditional ? Names{} : kFusedTonemaps;
        EXPECT_EQ(plan.executed_names(),
                  without(without(kHybridList, {"occlusion_culling"}), fused));
        EXPECT_TRUE(skipped_with_reason(plan, "occlusion_culling"));
        ASSERT_NE(named(plan, "depth_pyramid"), nullptr);
        EXPECT_FALSE(named(plan, "depth_pyramid")->skipped.has_value());
        const Draws mono = {{DrawStep::kMaskHidden, conditional ? kMonoDepthTested : kAlways},
                            {DrawStep::kChunks, kAlways},
                            {DrawStep::kSky, conditional ? kMonoAny : kAlways}};
        EXPECT_EQ(draws_of(plan, "mono.forward"), mono);
    }
}

TEST(FramePlan, NoOptNeitherBuildsThePyramidNorMasks) {
    for (bool conditional : {false, true}) {
        const FramePlan plan = plan_of(options_for(Mode::kHybrid),
                                       frame_with(false, MonoCulling::kNoOpt), conditional);
        const Names fused = conditional ? Names{} : kFusedTonemaps;
        EXPECT_EQ(plan.executed_names(),
                  without(without(kHybridList, {"depth_pyramid", "occlusion_culling"}), fused));
        EXPECT_TRUE(skipped_with_reason(plan, "depth_pyramid"));
        EXPECT_TRUE(skipped_with_reason(plan, "occlusion_culling"));
        const Draws mono = {{DrawStep::kChunks, kAlways},
                            {DrawStep::kSky, conditional ? kMonoAny : kAlways}};
        EXPECT_EQ(draws_of(plan, "mono.forward"), mono);
        ASSERT_NE(named(plan, "mono.forward"), nullptr);
        EXPECT_FALSE(contains(plan.reads(*named(plan, "mono.forward")), "merged_depth"));
    }
}

TEST(FramePlan, HybridFarfieldHasNoPyramidNoOcclusionCullingButComposites) {
    const Names expected = {"culling",       "shadow",         "left.forward",    "right.forward",
                            "mono.forward",  "left.composite", "right.composite", "left.tonemap",
                            "right.tonemap", "mono.tonemap",   "readback"};
    for (MonoCulling culling : kCullings) {
        for (bool conditional : {false, true}) {
            const FramePlan plan = plan_of(options_for(Mode::kHybridFarfield),
                                           frame_with(false, culling), conditional);
            EXPECT_EQ(plan.executed_names(),
                      conditional ? expected : without(expected, kFusedTonemaps))
                << mono_culling_name(culling);
            EXPECT_TRUE(skipped_with_reason(plan, "depth_pyramid"));
            EXPECT_TRUE(skipped_with_reason(plan, "occlusion_culling"));
            const Draws mono = {{DrawStep::kChunks, kAlways},
                                {DrawStep::kSky, conditional ? kMonoAny : kAlways}};
            EXPECT_EQ(draws_of(plan, "mono.forward"), mono) << mono_culling_name(culling);
        }
    }
}

TEST(FramePlan, SinglePassStereoDrawsBothEyesInOneForwardPass) {
    for (StereoPass stereo_pass : kSinglePasses) {
        const FramePlan plan = plan_of(options_for(Mode::kStereo, stereo_pass), PlanFrame{}, true);
        const Names expected = {"culling",      "shadow",        "eyes.forward",
                                "left.tonemap", "right.tonemap", "readback"};
        EXPECT_EQ(plan.executed_names(), expected) << stereo_pass_name(stereo_pass);
        const PlannedPass* eyes = named(plan, "eyes.forward");
        ASSERT_NE(eyes, nullptr);
        EXPECT_EQ(eyes->kind, PassKind::kForward);
        EXPECT_EQ(eyes->view, ViewId::kEyes);
        for (const char* image : {"left.hdr", "left.depth", "left.linear_depth", "right.hdr",
                                  "right.depth", "right.linear_depth"}) {
            EXPECT_TRUE(contains(plan.writes(*eyes), image))
                << stereo_pass_name(stereo_pass) << image;
        }
        const Draws draws = {{DrawStep::kChunks, kAlways}, {DrawStep::kSky, kAlways}};
        EXPECT_EQ(eyes->draws, draws);
    }
}

TEST(FramePlan, HybridSinglePassHasEyesForwardPlusMonoForward) {
    const Names expected = {
        "culling",           "shadow",        "eyes.forward",   "depth_pyramid",
        "occlusion_culling", "mono.forward",  "left.composite", "right.composite",
        "left.tonemap",      "right.tonemap", "mono.tonemap",   "readback"};
    for (StereoPass stereo_pass : kSinglePasses) {
        const FramePlan plan =
            plan_of(options_for(Mode::kHybrid, stereo_pass), frame_with(false), true);
        EXPECT_EQ(plan.executed_names(), expected) << stereo_pass_name(stereo_pass);
        const Draws eye = {{DrawStep::kChunks, kAlways}, {DrawStep::kSky, kMonoNone}};
        EXPECT_EQ(draws_of(plan, "eyes.forward"), eye);
    }
}

TEST(FramePlan, TaaResolvesEachEyeBeforeItsTonemap) {
    for (Mode mode : kModes) {
        for (StereoPass stereo_pass : kStereoPasses) {
            for (bool conditional : {false, true}) {
                PlanOptions options = options_for(mode, stereo_pass);
                // TAA reads the eye's HDR image after the composite, so its tone mapping is a
                // pass of its own, as separate_tonemap keeps it without TAA.
                options.separate_tonemap = true;
                const Names no_taa =
                    plan_of(options, frame_with(false), conditional).executed_names();
                options.separate_tonemap = false;
                options.anti_aliasing = AntiAliasing::kTaa;
                const FramePlan plan = plan_of(options, frame_with(false), conditional);
                const Names names = plan.executed_names();
                const std::string context = mode_name(mode) + " " + stereo_pass_name(stereo_pass);
                // TAA only adds the two resolves.
                EXPECT_EQ(without(names, {"left.taa", "right.taa"}), no_taa) << context;
                for (const std::string eye : {"left", "right"}) {
                    const std::ptrdiff_t taa = index_of(names, eye + ".taa");
                    ASSERT_GE(taa, 0) << context << " " << eye;
                    EXPECT_LT(taa, index_of(names, eye + ".tonemap")) << context << " " << eye;
                    if (mode != Mode::kStereo) {
                        // The resolve sees the composited image.
                        EXPECT_GT(taa, index_of(names, eye + ".composite")) << context;
                    }
                    const PlannedPass* tonemap = named(plan, eye + ".tonemap");
                    ASSERT_NE(tonemap, nullptr);
                    EXPECT_TRUE(contains(plan.reads(*tonemap), eye + ".history")) << context;
                    const PlannedPass* resolve = named(plan, eye + ".taa");
                    EXPECT_EQ(resolve->kind, PassKind::kTaa);
                    EXPECT_EQ(view_name(resolve->view), eye);
                }
                // Every forward pass writes its view's velocity (both eyes' for eyes.forward).
                for (const PlannedPass* pass : plan.executed()) {
                    if (pass->kind != PassKind::kForward) continue;
                    const Names views = pass->view == ViewId::kEyes ? Names{"left", "right"}
                                                                    : Names{view_name(pass->view)};
                    for (const std::string& view : views) {
                        EXPECT_TRUE(contains(plan.writes(*pass), view + ".velocity"))
                            << context << " " << pass->name;
                    }
                }
                // And without TAA nothing writes a velocity.
                const FramePlan plain =
                    plan_of(options_for(mode, stereo_pass), frame_with(false), conditional);
                for (const PlannedPass* pass : plain.executed()) {
                    for (const std::string& write : plain.writes(*pass)) {
                        EXPECT_EQ(write.find("velocity"), std::string::npos) << pass->name;
                    }
                }
            }
        }
    }
    PlanOptions options = options_for(Mode::kStereo);
    options.anti_aliasing = AntiAliasing::kTaa;
    const FramePlan plan = plan_of(options, PlanFrame{}, false);
    const Draws eye = {{DrawStep::kChunks, kAlways}, {DrawStep::kSky, kAlways}};
    EXPECT_EQ(draws_of(plan, "left.forward"), eye);
}

TEST(FramePlan, SsaoRunsAfterTheCompositesAndMonoSsaoRightAfterMonoForward) {
    for (Mode mode : kModes) {
        for (AntiAliasing aa : kAntiAliasings) {
            for (StereoPass stereo_pass : kStereoPasses) {
                PlanOptions options = options_for(mode, stereo_pass);
                options.anti_aliasing = aa;
                const Names no_ssao = plan_of(options, frame_with(false), true).executed_names();
                options.ssao = true;
                const FramePlan plan = plan_of(options, frame_with(false), true);
                const Names names = plan.executed_names();
                const std::string context = mode_name(mode) + " " + anti_aliasing_name(aa) + " " +
                                            stereo_pass_name(stereo_pass);
                EXPECT_EQ(without(names, {"ssao", "mono.ssao"}), no_ssao) << context;
                const std::ptrdiff_t ssao = index_of(names, "ssao");
                ASSERT_GE(ssao, 0) << context;
                std::ptrdiff_t first_post = static_cast<std::ptrdiff_t>(names.size());
                for (const char* name :
                     {"left.taa", "right.taa", "left.tonemap", "right.tonemap", "mono.tonemap"}) {
                    const std::ptrdiff_t i = index_of(names, name);
                    if (i >= 0) first_post = std::min(first_post, i);
                }
                EXPECT_LT(ssao, first_post) << context;
                for (const char* name :
                     {"left.forward", "right.forward", "eyes.forward", "mono.forward"}) {
                    EXPECT_GT(ssao, index_of(names, name)) << context << " " << name;
                }
                if (mode == Mode::kStereo) {
                    EXPECT_EQ(named(plan, "mono.ssao"), nullptr) << context;
                    continue;
                }
                EXPECT_GT(ssao, index_of(names, "left.composite")) << context;
                EXPECT_GT(ssao, index_of(names, "right.composite")) << context;
                const std::ptrdiff_t mono_ssao = index_of(names, "mono.ssao");
                ASSERT_GE(mono_ssao, 0) << context;
                EXPECT_EQ(mono_ssao, index_of(names, "mono.forward") + 1) << context;
                EXPECT_LT(mono_ssao, index_of(names, "left.composite")) << context;
                EXPECT_LT(mono_ssao, index_of(names, "right.composite")) << context;
            }
        }
    }
    PlanOptions options = options_for(Mode::kHybrid);
    options.ssao = true;
    options.anti_aliasing = AntiAliasing::kTaa;
    const Names expected = {"culling",         "shadow",        "left.forward",
                            "right.forward",   "depth_pyramid", "occlusion_culling",
                            "mono.forward",    "mono.ssao",     "left.composite",
                            "right.composite", "ssao",          "left.taa",
                            "right.taa",       "left.tonemap",  "right.tonemap",
                            "mono.tonemap",    "readback"};
    EXPECT_EQ(plan_of(options, frame_with(false), true).executed_names(), expected);
}

TEST(FramePlan, DepthPrepassStartsEveryForwardPassAfterTheMask) {
    for (Mode mode : kModes) {
        for (MonoCulling culling : kCullings) {
            for (StereoPass stereo_pass : kStereoPasses) {
                for (bool conditional : {false, true}) {
                    PlanOptions options = options_for(mode, stereo_pass);
                    options.depth_prepass = true;
                    const FramePlan plan =
                        plan_of(options, frame_with(false, culling), conditional);
                    for (const PlannedPass* pass : plan.executed()) {
                        if (pass->kind != PassKind::kForward) continue;
                        const std::string context =
                            mode_name(mode) + " " + mono_culling_name(culling) + " " + pass->name;
                        ASSERT_FALSE(pass->draws.empty()) << context;
                        std::size_t first = 0;
                        if (pass->draws[0].step == DrawStep::kMaskHidden) {
                            EXPECT_EQ(pass->view, ViewId::kMono) << context;
                            first = 1;
                        }
                        ASSERT_GT(pass->draws.size(), first) << context;
                        EXPECT_EQ(pass->draws[first].step, DrawStep::kDepthPrepass) << context;
                    }
                }
            }
        }
    }
    PlanOptions stereo = options_for(Mode::kStereo);
    stereo.depth_prepass = true;
    const Draws stereo_eye = {{DrawStep::kDepthPrepass, kAlways},
                              {DrawStep::kChunks, kAlways},
                              {DrawStep::kSky, kAlways}};
    EXPECT_EQ(draws_of(plan_of(stereo, PlanFrame{}, true), "left.forward"), stereo_eye);
    PlanOptions hybrid = options_for(Mode::kHybrid);
    hybrid.depth_prepass = true;
    const FramePlan plan = plan_of(hybrid, frame_with(false), true);
    const Draws eye = {{DrawStep::kDepthPrepass, kAlways},
                       {DrawStep::kChunks, kAlways},
                       {DrawStep::kSky, kMonoNone}};
    EXPECT_EQ(draws_of(plan, "right.forward"), eye);
    const Draws mono = {{DrawStep::kMaskHidden, kMonoDepthTested},
                        {DrawStep::kDepthPrepass, kAlways},
                        {DrawStep::kChunks, kAlways},
                        {DrawStep::kSky, kMonoAny}};
    EXPECT_EQ(draws_of(plan, "mono.forward"), mono);
}

TEST(FramePlan, RoutingDebugViewColoursChunksInEveryForwardPass) {
    for (Mode mode : kModes) {
        for (StereoPass stereo_pass : kStereoPasses) {
            PlanFrame frame = frame_with(false);
            frame.debug = DebugView::kRouting;
            const FramePlan plan = plan_of(options_for(mode, stereo_pass), frame, true);
            int forward = 0;
            for (const PlannedPass* pass : plan.executed()) {
                if (pass->kind != PassKind::kForward) continue;
                ++forward;
                int routing = 0;
                for (const PlannedDraw& draw : pass->draws) {
                    EXPECT_NE(draw.step, DrawStep::kChunks) << mode_name(mode) << " " << pass->name;
                    if (draw.step == DrawStep::kChunksShowRouting) ++routing;
                }
                EXPECT_EQ(routing, 1) << mode_name(mode) << " " << pass->name;
            }
            EXPECT_GT(forward, 0);
        }
    }
    PlanFrame frame;
    frame.debug = DebugView::kRouting;
    const Draws eye = {{DrawStep::kChunksShowRouting, kAlways}, {DrawStep::kSky, kAlways}};
    EXPECT_EQ(draws_of(plan_of(options_for(Mode::kStereo), frame, false), "left.forward"), eye);
}

TEST(FramePlan, UnchangedLightRegionSkipsTheShadowPassWithAReason) {
    for (Mode mode : kModes) {
        PlanFrame frame = frame_with(false);
        frame.shadow_needed = false;
        const FramePlan plan = plan_of(options_for(mode), frame, true);
        EXPECT_TRUE(skipped_with_reason(plan, "shadow")) << mode_name(mode);
        const Names full = plan_of(options_for(mode), frame_with(false), true).executed_names();
        EXPECT_EQ(plan.executed_names(), without(full, {"shadow"})) << mode_name(mode);
    }
    PlanFrame frame;
    frame.shadow_needed = false;
    EXPECT_EQ(plan_of(options_for(Mode::kStereo), frame, false).executed_names(),
              without(kStereoList, {"shadow"}));
}

TEST(FramePlan, MonoTonemapOnlyWhenReadBack) {
    PlanOptions options = options_for(Mode::kHybrid);
    options.read_back = false;
    const FramePlan plan = plan_of(options, frame_with(false), true);
    EXPECT_TRUE(skipped_with_reason(plan, "mono.tonemap"));
    EXPECT_EQ(plan.executed_names(), without(kHybridList, {"mono.tonemap"}));
    ASSERT_NE(named(plan, "readback"), nullptr);
    EXPECT_FALSE(contains(plan.reads(*named(plan, "readback")), "mono.display"));

    const FramePlan read = plan_of(options_for(Mode::kHybrid), frame_with(false), true);
    ASSERT_NE(named(read, "mono.tonemap"), nullptr);
    EXPECT_FALSE(named(read, "mono.tonemap")->skipped.has_value());
    EXPECT_TRUE(contains(read.reads(*named(read, "readback")), "mono.display"));
}

// One full-screen pass per eye (issue 33): where nothing but the eye's tone mapping reads its HDR
// image after the composite, the composite writes the display image itself. With predicates the
// tonemap stays, if mono-none (the GPU skips the composite exactly then), keeping what the
// composite wrote otherwise; without them C always draws and the tonemap is left out, saying why.
TEST(FramePlan, CompositeWritesTheDisplayWhereOnlyTheTonemapReadsTheHdr) {
    for (Mode mode : kHybridModes) {
        for (StereoPass stereo_pass : kStereoPasses) {
            for (MonoCulling culling : kCullings) {
                for (DebugView debug :
                     {DebugView::kNone, DebugView::kTintMono, DebugView::kStereoOnly,
                      DebugView::kMonoOnly, DebugView::kRouting}) {
                    for (bool conditional : {false, true}) {
                        for (bool extras : {false, true}) {
                            // What reads the eyes' linear depth and display images changes
                            // nothing: the composite still writes the linear depth.
                            PlanOptions options = options_for(mode, stereo_pass);
                            options.read_back = !extras;
                            options.read_back_depth = extras;
                            options.depth_histogram = extras;
                            options.depth_prepass = extras;
                            PlanFrame frame = frame_with(false, culling);
                            frame.debug = debug;
                            const std::string context =
                                mode_name(mode) + " " + stereo_pass_name(stereo_pass) + " " +
                                mono_culling_name(culling) + " debug " +
                                std::to_string(static_cast<int>(debug)) + " conditional " +
                                std::to_string(conditional) + " extras " + std::to_string(extras);
                            expect_fused(plan_of(options, frame, conditional), conditional,
                                         context);
                        }
                    }
                }
            }
        }
    }
}

// TAA (it resolves the eye's HDR image) and SSAO (it blends its AO into it) read the linear colour
// after the composite: the tone mapping stays a pass of its own, as separate_tonemap keeps it, and
// as on a device without independentBlend (the composite could not leave the linear depth alone).
TEST(FramePlan, TaaSsaoOrSeparateTonemapKeepTheToneMappingAPassOfItsOwn) {
    for (Mode mode : kHybridModes) {
        for (StereoPass stereo_pass : kStereoPasses) {
            for (bool conditional : {false, true}) {
                for (int reader = 0; reader < 5; ++reader) {
                    PlanOptions options = options_for(mode, stereo_pass);
                    options.anti_aliasing = reader == 0 ? AntiAliasing::kTaa : AntiAliasing::kNone;
                    options.ssao = reader == 1 || reader == 2;
                    options.ssao_stereo = reader == 2;
                    options.separate_tonemap = reader == 3;
                    const FramePlan plan = plan_frame(options, frame_with(false),
                                                      PlanDevice{conditional, reader != 4});
                    const std::string context =
                        mode_name(mode) + " " + stereo_pass_name(stereo_pass) + " reader " +
                        std::to_string(reader) + " conditional " + std::to_string(conditional);
                    for (const std::string eye : {"left", "right"}) {
                        const PlannedPass* composite = named(plan, eye + ".composite");
                        const PlannedPass* tonemap = named(plan, eye + ".tonemap");
                        ASSERT_NE(composite, nullptr) << context;
                        ASSERT_NE(tonemap, nullptr) << context;
                        EXPECT_FALSE(composite->writes_display) << context;
                        EXPECT_TRUE(contains(plan.writes(*composite), eye + ".hdr")) << context;
                        EXPECT_FALSE(contains(plan.writes(*composite), eye + ".display"))
                            << context;
                        EXPECT_FALSE(tonemap->skipped.has_value()) << context;
                        EXPECT_EQ(tonemap->when, kAlways) << context;
                        EXPECT_EQ(plan.reads(*tonemap),
                                  Names{eye + (reader == 0 ? ".history" : ".hdr")})
                            << context;
                    }
                }
            }
        }
    }
    // separate_tonemap is the plan as it was before the composite could write the display image.
    for (bool conditional : {false, true}) {
        PlanOptions options = options_for(Mode::kHybrid);
        options.separate_tonemap = true;
        EXPECT_EQ(plan_of(options, frame_with(false), conditional).executed_names(), kHybridList);
    }
}

// Nothing beyond the plane, or stereo: no composite, so nothing to fuse; the flag changes nothing.
TEST(FramePlan, WithoutACompositeTheTonemapAlwaysRunsAndSeparateTonemapChangesNothing) {
    for (Mode mode : kModes) {
        for (bool conditional : {false, true}) {
            for (bool mono_skipped : {false, true}) {
                if (mode != Mode::kStereo && !mono_skipped) continue;
                PlanOptions options = options_for(mode);
                const FramePlan plan = plan_of(options, frame_with(mono_skipped), conditional);
                options.separate_tonemap = true;
                const FramePlan separate = plan_of(options, frame_with(mono_skipped), conditional);
                const std::string context =
                    mode_name(mode) + " conditional " + std::to_string(conditional);
                ASSERT_EQ(plan.executed_names(), separate.executed_names()) << context;
                for (std::size_t i = 0; i < plan.executed().size(); ++i) {
                    expect_same_pass(plan, *plan.executed()[i], separate, *separate.executed()[i],
                                     context);
                }
                for (const std::string eye : {"left", "right"}) {
                    const PlannedPass* tonemap = named(plan, eye + ".tonemap");
                    ASSERT_NE(tonemap, nullptr) << context;
                    EXPECT_FALSE(tonemap->skipped.has_value()) << context;
                    EXPECT_EQ(tonemap->when, kAlways) << context;
                }
            }
        }
    }
}

// Blended chunks (alphaMode BLEND) are drawn last in every view; in hybrid the eyes draw theirs
// after the composite, into the HDR image the composite wrote, tested against its linear depth,
// so the composite no longer writes the display image.
TEST(FramePlan, BlendedChunksDrawLastAndInHybridAfterTheComposite) {
    for (bool conditional : {false, true}) {
        PlanOptions stereo = options_for(Mode::kStereo);
        stereo.blended = true;
        const FramePlan stereo_plan = plan_of(stereo, PlanFrame{}, conditional);
        EXPECT_EQ(stereo_plan.executed_names(), kStereoList);
        const Draws eye = {
            {DrawStep::kChunks, kAlways}, {DrawStep::kSky, kAlways}, {DrawStep::kBlended, kAlways}};
        EXPECT_EQ(draws_of(stereo_plan, "left.forward"), eye);
        EXPECT_EQ(draws_of(stereo_plan, "right.forward"), eye);

        PlanOptions hybrid = options_for(Mode::kHybrid);
        hybrid.blended = true;
        const FramePlan plan = plan_of(hybrid, frame_with(false), conditional);
        const Names expected = {"culling",
                                "shadow",
                                "left.forward",
                                "right.forward",
                                "depth_pyramid",
                                "occlusion_culling",
                                "mono.forward",
                                "left.composite",
                                "right.composite",
                                "left.transparency",
                                "right.transparency",
                                "left.tonemap",
                                "right.tonemap",
                                "mono.tonemap",
                                "readback"};
        EXPECT_EQ(plan.executed_names(), expected) << conditional;
        for (const std::string name : {"left.forward", "right.forward"}) {
            for (const PlannedDraw& draw : draws_of(plan, name)) {
                EXPECT_NE(draw.step, DrawStep::kBlended) << name;
            }
        }
        ASSERT_FALSE(draws_of(plan, "mono.forward").empty());
        EXPECT_EQ(draws_of(plan, "mono.forward").back(),
                  (PlannedDraw{DrawStep::kBlended, kAlways}));
        for (const std::string e : {"left", "right"}) {
            const PlannedPass* pass = named(plan, e + ".transparency");
            ASSERT_NE(pass, nullptr);
            EXPECT_EQ(pass->kind, PassKind::kTransparency);
            EXPECT_EQ(pass->when, kAlways);  // an eye's own blended chunks, whatever C drew
            EXPECT_EQ(plan.reads(*pass), (Names{"draw_lists", "predicates", "shadow_map",
                                                e + ".linear_depth", e + ".hdr"}));
            EXPECT_EQ(plan.writes(*pass), (Names{e + ".hdr"}));
            EXPECT_FALSE(named(plan, e + ".composite")->writes_display) << e;
        }
        // Nothing beyond m: stereo's passes and draws exactly, blended chunks in the forward
        // passes.
        const FramePlan skipped = plan_of(hybrid, frame_with(true), conditional);
        EXPECT_EQ(skipped.executed_names(), kStereoList);
        EXPECT_EQ(draws_of(skipped, "left.forward"), eye);
        // Single-pass stereo: one forward pass for both eyes, a transparency pass per eye.
        PlanOptions single = options_for(Mode::kHybrid, StereoPass::kInstanced);
        single.blended = true;
        const Names names = plan_of(single, frame_with(false), conditional).executed_names();
        EXPECT_LT(index_of(names, "right.composite"), index_of(names, "left.transparency"));
        EXPECT_LT(index_of(names, "left.transparency"), index_of(names, "right.transparency"));
        EXPECT_LT(index_of(names, "right.transparency"), index_of(names, "left.tonemap"));
        // With TAA and SSAO: after the composites, before the eyes' SSAO and TAA.
        PlanOptions post = hybrid;
        post.anti_aliasing = AntiAliasing::kTaa;
        post.ssao = true;
        const Names with_post = plan_of(post, frame_with(false), conditional).executed_names();
        EXPECT_LT(index_of(with_post, "right.transparency"), index_of(with_post, "ssao"));
        EXPECT_LT(index_of(with_post, "ssao"), index_of(with_post, "left.taa"));
    }
}

// --mono-plane auto: both eyes' final depth is counted after everything that writes it (the
// composites, SSAO's apply, TAA reads it) and before the read-back; nothing else changes.
TEST(FramePlan, AutoMonoPlaneCountsTheEyesFinalDepthBeforeTheReadBack) {
    for (const bool mono_skipped : {false, true}) {
        PlanOptions options = options_for(Mode::kHybrid);
        options.anti_aliasing = AntiAliasing::kTaa;
        const FramePlan plain = plan_of(options, frame_with(mono_skipped), true);
        options.depth_histogram = true;
        const FramePlan counted = plan_of(options, frame_with(mono_skipped), true);
        std::vector<std::string> expected = plain.executed_names();
        expected.insert(expected.end() - 1, "depth_histogram");
        EXPECT_EQ(counted.executed_names(), expected);
        const PlannedPass* pass = named(counted, "depth_histogram");
        ASSERT_NE(pass, nullptr);
        EXPECT_EQ(pass->kind, PassKind::kDepthHistogram);
        EXPECT_EQ(counted.reads(*pass),
                  (std::vector<std::string>{"left.linear_depth", "right.linear_depth"}));
        // It clears the bins first, and the host reads them after the frame.
        EXPECT_EQ(counted.writes(*pass), (std::vector<std::string>{"depth_histogram"}));
    }
}

// One combination of the options the generic checks go over.
struct Combination {
    PlanOptions options;
    PlanFrame frame;
    bool conditional = false;

    std::string text() const {
        std::ostringstream s;
        s << mode_name(options.mode) << " " << stereo_pass_name(options.stereo_pass) << " "
          << mono_culling_name(frame.mono_culling) << " "
          << anti_aliasing_name(options.anti_aliasing) << " ssao " << options.ssao << " prepass "
          << options.depth_prepass << " read_back " << options.read_back << " conditional "
          << conditional << " mono_skipped " << frame.mono_skipped << " shadow_needed "
          << frame.shadow_needed << " debug " << static_cast<int>(frame.debug) << " blended "
          << options.blended;
        return s.str();
    }
};

// Modes x culling variants x AA none/TAA x SSAO x stereo passes x depth prepass x conditional
// rendering x mono_skipped x shadow needed x read-back x debug views x blended chunks.
std::vector<Combination> all_combinations() {
    std::vector<Combination> all;
    for (Mode mode : kModes)
        for (MonoCulling culling : kCullings)
            for (AntiAliasing aa : kAntiAliasings)
                for (bool ssao : {false, true})
                    for (StereoPass stereo_pass : kStereoPasses)
                        for (bool prepass : {false, true})
                            for (bool conditional : {false, true})
                                for (bool mono_skipped : {false, true})
                                    for (bool shadow_needed : {false, true})
                                        for (bool read_back : {false, true})
                                            for (DebugView debug :
                                                 {DebugView::kNone, DebugView::kRouting,
                                                  DebugView::kMonoOnly})
                                                for (bool blended : {false, true}) {
                                                    Combination c;
                                                    c.options.blended = blended;
                                                    c.options.mode = mode;
                                                    c.options.stereo_pass = stereo_pass;
                                                    c.options.anti_aliasing = aa;
                                                    c.options.ssao = ssao;
                                                    c.options.depth_prepass = prepass;
                                                    c.options.read_back = read_back;
                                                    // The renderer refuses AO read-back without
                                                    // SSAO.
                                                    c.options.read_back_ao = ssao && read_back;
                                                    c.options.read_back_depth = read_back;
                                                    c.options.read_back_draw_lists = !read_back;
                                                    c.frame = frame_with(mono_skipped, culling);
                                                    c.frame.shadow_needed = shadow_needed;
                                                    c.frame.debug = debug;
                                                    c.conditional = conditional;
                                                    all.push_back(c);
                                                }
    return all;
}

// Persistent across frames: what a pass may read that no pass of this frame wrote.
bool persistent_input(const std::string& resource, const FramePlan& plan) {
    if (resource == "left.history_previous" || resource == "right.history_previous") return true;
    const PlannedPass* shadow = named(plan, "shadow");
    return resource == "shadow_map" && shadow != nullptr && shadow->skipped.has_value();
}

TEST(FramePlan, EveryReadIsPrecededByAWriteOverAllOptions) {
    const std::vector<Combination> all = all_combinations();
    EXPECT_EQ(all.size(), 3u * 3 * 2 * 2 * 4 * 2 * 2 * 2 * 2 * 2 * 3 * 2);
    for (const Combination& c : all) {
        const FramePlan plan = plan_of(c.options, c.frame, c.conditional);
        std::set<std::string> written;
        std::set<std::string> names;
        for (const PlannedPass& pass : plan.passes) {
            EXPECT_TRUE(names.insert(pass.name).second)
                << c.text() << ": " << pass.name << " twice";
            if (pass.skipped) {
                EXPECT_FALSE(pass.skipped->empty()) << c.text() << ": " << pass.name;
                continue;
            }
            // Step by step: SSAO writes its AO images before its apply steps read them.
            for (const graph::Step& step : pass.steps) {
                for (const graph::ResourceUse& use : step.uses) {
                    const graph::UseScope scope = graph::use_scope(use.use);
                    const std::string& name = plan.resources[use.resource].name;
                    if (scope.writes && use.use != graph::Use::kColorBlend) continue;
                    EXPECT_TRUE(written.contains(name) || persistent_input(name, plan))
                        << c.text() << ": " << pass.name << "/" << step.name << " reads " << name
                        << " before any pass wrote it";
                }
                for (const graph::ResourceUse& use : step.uses) {
                    if (graph::use_scope(use.use).writes) {
                        written.insert(plan.resources[use.resource].name);
                    }
                }
            }
        }
        ASSERT_FALSE(plan.passes.empty()) << c.text();
        EXPECT_EQ(plan.passes.front().name, "culling") << c.text();
        EXPECT_EQ(plan.passes.back().name, "readback") << c.text();
        // Without conditional rendering nothing is predicated.
        if (!c.conditional) {
            for (const PlannedPass& pass : plan.passes) {
                EXPECT_EQ(pass.when, kAlways) << c.text() << ": " << pass.name;
                for (const PlannedDraw& draw : pass.draws) {
                    EXPECT_EQ(draw.when, kAlways) << c.text() << ": " << pass.name;
                }
            }
        }
        // Nothing beyond the mono plane: stereo's passes exactly.
        if (c.options.mode != Mode::kStereo && c.frame.mono_skipped) {
            PlanOptions stereo = c.options;
            stereo.mode = Mode::kStereo;
            EXPECT_EQ(plan.executed_names(),
                      plan_of(stereo, c.frame, c.conditional).executed_names())
                << c.text();
        }
    }
}

// Every planned pass is named by its kind and view alone, the name reads back to them, and
// the plan finds each pass by kind and view: the names the documentation and bench.json show.
TEST(FramePlan, PassesAreFoundByKindAndViewAndTheirNamesReadBack) {
    for (const Combination& c : all_combinations()) {
        const FramePlan plan = plan_of(c.options, c.frame, c.conditional);
        for (const PlannedPass& pass : plan.passes) {
            EXPECT_EQ(pass.name, pass_name(pass.kind, pass.view)) << c.text();
            const auto parsed = parse_pass_name(pass.name);
            ASSERT_TRUE(parsed.has_value()) << pass.name;
            EXPECT_EQ(parsed->first, pass.kind) << pass.name;
            EXPECT_EQ(parsed->second, pass.view) << pass.name;
            EXPECT_EQ(plan.find(pass.kind, pass.view), &pass) << pass.name << " " << c.text();
            EXPECT_EQ(plan.runs(pass.kind, pass.view), !pass.skipped.has_value()) << pass.name;
        }
    }
    // The names as the pages and bench.json spell them, written out here.
    EXPECT_EQ(pass_name(PassKind::kSsao, ViewId::kMono), "mono.ssao");
    EXPECT_EQ(pass_name(PassKind::kSsao, ViewId::kNone), "ssao");
    EXPECT_EQ(pass_name(PassKind::kForward, ViewId::kEyes), "eyes.forward");
    EXPECT_EQ(pass_name(PassKind::kDepthPyramid, ViewId::kNone), "depth_pyramid");
    EXPECT_EQ(pass_name(PassKind::kTransparency, ViewId::kRight), "right.transparency");
    for (const char* unknown : {"", "forward.left", "left.", ".forward", "left.unknown",
                                "nobody.forward", "left.forward.x"}) {
        EXPECT_FALSE(parse_pass_name(unknown).has_value()) << unknown;
    }
    const FramePlan stereo = plan_of(options_for(Mode::kStereo), frame_with(false), false);
    EXPECT_EQ(stereo.find(PassKind::kComposite, ViewId::kLeft), nullptr);
    EXPECT_FALSE(stereo.runs(PassKind::kComposite, ViewId::kLeft));
    EXPECT_EQ(stereo.find(PassKind::kForward), nullptr) << "the eyes' forward passes have views";
}

// runs_only_in_hybrid against the plans themselves: a pass is hybrid's alone exactly when the
// stereo plan of the same options and frame has no pass of that kind and view.
TEST(FramePlan, RunsOnlyInHybridIsWhatStereoPlansNeverHave) {
    std::set<std::string> seen;
    for (const Combination& c : all_combinations()) {
        if (c.options.mode == Mode::kStereo) continue;
        PlanOptions stereo_options = c.options;
        stereo_options.mode = Mode::kStereo;
        const FramePlan stereo = plan_of(stereo_options, c.frame, c.conditional);
        const FramePlan hybrid = plan_of(c.options, c.frame, c.conditional);
        for (const PlannedPass& pass : hybrid.passes) {
            const bool in_stereo = stereo.find(pass.kind, pass.view) != nullptr;
            EXPECT_EQ(runs_only_in_hybrid(pass.kind, pass.view), !in_stereo)
                << pass.name << " " << c.text();
            if (!in_stereo) seen.insert(pass.name);
        }
    }
    // The list the auto mono plane's chooser once kept by hand lacked C's SSAO.
    const std::set<std::string> expected = {
        "mono.forward",      "depth_pyramid",      "occlusion_culling",
        "mono.ssao",         "left.composite",     "right.composite",
        "left.transparency", "right.transparency", "mono.tonemap"};
    EXPECT_EQ(seen, expected);
}

TEST(FramePlan, NamesOfKindsPredicatesAndStepsAreNonEmptyAndDistinct) {
    const std::vector<PassKind> kinds = {PassKind::kCulling,
                                         PassKind::kShadow,
                                         PassKind::kForward,
                                         PassKind::kDepthPyramid,
                                         PassKind::kOcclusionCulling,
                                         PassKind::kComposite,
                                         PassKind::kTransparency,
                                         PassKind::kSsao,
                                         PassKind::kTaa,
                                         PassKind::kTonemap,
                                         PassKind::kDepthHistogram,
                                         PassKind::kReadback};
    const std::vector<GpuPredicate> predicates = {GpuPredicate::kAlways, GpuPredicate::kMonoAny,
                                                  GpuPredicate::kMonoNone,
                                                  GpuPredicate::kMonoDepthTested};
    const std::vector<DrawStep> steps = {DrawStep::kMaskHidden, DrawStep::kDepthPrepass,
                                         DrawStep::kChunks,     DrawStep::kChunksShowRouting,
                                         DrawStep::kSky,        DrawStep::kBlended};
    const auto check = [](const std::vector<std::string>& names) {
        const std::set<std::string> distinct(names.begin(), names.end());
        EXPECT_EQ(distinct.size(), names.size()) << joined(names);
        for (const std::string& name : names) {
            EXPECT_FALSE(name.empty());
            EXPECT_NE(name, "?");
        }
    };
    std::vector<std::string> names;
    for (PassKind kind : kinds) names.push_back(pass_kind_name(kind));
    check(names);
    names.clear();
    for (GpuPredicate predicate : predicates) names.push_back(gpu_predicate_name(predicate));
    check(names);
    names.clear();
    for (DrawStep step : steps) names.push_back(draw_step_name(step));
    check(names);
    EXPECT_EQ(gpu_predicate_name(GpuPredicate::kAlways), "always");
    EXPECT_EQ(gpu_predicate_name(GpuPredicate::kMonoAny), "mono-any");
    EXPECT_EQ(draw_step_name(DrawStep::kMaskHidden), "mask-hidden");
    EXPECT_EQ(draw_step_name(DrawStep::kDepthPrepass), "depth-prepass");
    EXPECT_EQ(draw_step_name(DrawStep::kChunks), "chunks");
}

// The plan as docs/architecture.md shows it: one line a pass, its view, its predicate, its draws
// (with theirs) or why the frame leaves it out.
std::string plan_text(const FramePlan& plan) {
    std::string out;
    for (const PlannedPass& pass : plan.passes) {
        std::ostringstream line;
        line << "  " << std::left << std::setw(18) << pass.name << std::setw(7)
             << (pass.view == ViewId::kNone ? "-" : view_name(pass.view));
        if (pass.skipped) {
            line << "skipped: " << *pass.skipped;
        } else {
            std::vector<std::string> details;
            if (pass.when != GpuPredicate::kAlways) {
                details.push_back("if " + gpu_predicate_name(pass.when));
            }
            if (pass.writes_display)
                details.push_back("writes " + view_name(pass.view) + ".display");
            if (!pass.draws.empty()) {
                std::string draws = "draws:";
                for (const PlannedDraw& draw : pass.draws) {
                    std::ostringstream text;
                    PrintTo(draw, &text);
                    draws += (draws.back() == ':' ? " " : ", ") + text.str();
                }
                details.push_back(draws);
            }
            for (std::size_t i = 0; i < details.size(); ++i) line << (i ? "; " : "") << details[i];
        }
        std::string text = line.str();
        text.erase(text.find_last_not_of(' ') + 1);
        out += text + "\n";
    }
    return out;
}

// docs/architecture.md prints these plans as this code makes them: each block must stand there
// verbatim (a changed rule makes the page stale, and this test says so). With
// MONOPLANE_PRINT_PLANS set the blocks are printed, to paste into the page.
TEST(FramePlanPrint, ArchitecturePageShowsThePlansAsTheCodeMakesThem) {
    const PlanDevice conditional{true};
    PlanOptions post = options_for(Mode::kHybrid);
    post.anti_aliasing = AntiAliasing::kTaa;
    post.ssao = true;
    const std::vector<std::pair<std::string, FramePlan>> plans = {
        {"stereo", plan_frame(options_for(Mode::kStereo), PlanFrame{}, conditional)},
        {"stereo-gs", plan_frame(options_for(Mode::kStereo, StereoPass::kGeometryShader),
                                 PlanFrame{}, conditional)},
        {"hybrid, m = 8, occlusion-cull, conditional rendering",
         plan_frame(options_for(Mode::kHybrid), frame_with(false), conditional)},
        {"hybrid, m = 8, occlusion-cull, without conditional rendering",
         plan_frame(options_for(Mode::kHybrid), frame_with(false), PlanDevice{false})},
        {"hybrid, m = far (mono_skipped)",
         plan_frame(options_for(Mode::kHybrid), frame_with(true), conditional)},
        {"hybrid, m = 8, occlusion-cull, TAA + SSAO, conditional rendering",
         plan_frame(post, frame_with(false), conditional)},
        {"hybrid-farfield, m = 8, conditional rendering",
         plan_frame(options_for(Mode::kHybridFarfield), frame_with(false), conditional)},
    };
    std::ifstream file(MONOPLANE_ARCHITECTURE_PAGE);
    ASSERT_TRUE(file) << MONOPLANE_ARCHITECTURE_PAGE;
    const std::string page((std::istreambuf_iterator<char>(file)),
                           std::istreambuf_iterator<char>());
    const bool print = std::getenv("MONOPLANE_PRINT_PLANS") != nullptr;
    for (const auto& [title, plan] : plans) {
        const std::string text = plan_text(plan);
        if (print) std::cout << "# " << title << "\n" << text << "\n";
        EXPECT_NE(page.find("```text\n" + text + "```"), std::string::npos)
            << title << ": docs/architecture.md does not show this plan:\n"
            << text;
    }
}

}  // namespace
}  // namespace monoplane::plan
