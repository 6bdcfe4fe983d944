// A pass kind written as one unit (renderer/plan/pass_unit.h): plan_frame places it at its slot
// when the frame asks for it, its passes are planned passes like the built-in kinds' (named,
// culled, found), and what it may touch at record time is what each step declared. The unit here
// is the tests' own ("probe": each eye's linear depth into its display image, as a debug view
// would), written out by hand, so that the plans compared do not come from the renderer's units.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "renderer/passes/pass_unit_declarations.h"
#include "renderer/passes/ssao/ssao_steps.h"
#include "renderer/plan/frame_plan.h"
#include "renderer/plan/frame_plan_json.h"
#include "renderer/plan/pass_unit.h"

namespace monoplane::plan {
namespace {

using Names = std::vector<std::string>;

void place_probe(UnitPlacement& placement) {
    if (!placement.debug_view_shown()) return;
    for (ViewId eye : kEyeViews) {
        PlannedPass& pass = placement.add_pass(eye);
        graph::Step& step = pass.steps.emplace_back();
        step.name = "draw";
        graph::StepBuilder(step)
            .use(placement.resources().image(eye, ImageRole::kLinearDepth),
                 graph::Use::kSampledFragment)
            .use(placement.resources().image(eye, ImageRole::kDisplay), graph::Use::kColorWrite);
    }
}

PassUnitDeclaration probe() {
    PassUnitDeclaration unit;
    unit.name = "probe";
    unit.debug_view = "probe-view";
    unit.place = &place_probe;
    return unit;
}

// The registered units (every kind) and the probe after them, as a renderer with the
// probe registered would plan.
std::vector<PassUnitDeclaration> with_probe() {
    std::vector<PassUnitDeclaration> units = passes::pass_unit_declarations();
    units.push_back(probe());
    return units;
}

PlanFrame showing(const std::string& unit_debug_view, bool mono_skipped = false) {
    PlanFrame frame;
    frame.mono_skipped = mono_skipped;
    frame.unit_debug_view = unit_debug_view;
    return frame;
}

PlanOptions options_for(Mode mode, bool taa = false, bool ssao = false) {
    PlanOptions options;
    options.mode = mode;
    if (taa) options.anti_aliasing = AntiAliasing::kTaa;
    options.ssao = ssao;
    return options;
}

TEST(PassUnit, PlacedOnlyWhenItsDebugViewIsShownAndOtherwiseLeavesThePlanAsItWas) {
    const std::vector<PassUnitDeclaration> units = with_probe();
    for (Mode mode : {Mode::kStereo, Mode::kHybrid, Mode::kHybridFarfield}) {
        for (const std::string& other : {std::string(), std::string("another-view")}) {
            const FramePlan with =
                plan_frame(options_for(mode), showing(other), PlanDevice{}, units);
            const FramePlan without =
                passes::plan_frame(options_for(mode), showing(other), PlanDevice{});
            EXPECT_EQ(with.executed_names(), without.executed_names()) << mode_name(mode);
            EXPECT_EQ(with.find_unit("probe", ViewId::kLeft), nullptr) << mode_name(mode);
        }
    }
}

// Stereo, shown: the unit's passes run after the tone mapping and before the read-back, by the
// names pass_name would give a kind of that name; the tone mapping, whose display image the unit
// overwrites whole and nobody reads before, is culled, and with it everything only it read.
TEST(PassUnit, StereoShowsItAfterTheToneMappingAndCullsWhatItOverwrites) {
    const FramePlan plan =
        plan_frame(options_for(Mode::kStereo), showing("probe-view"), PlanDevice{}, with_probe());
    const Names expected = {"culling",    "shadow",      "left.forward", "right.forward",
                            "left.probe", "right.probe", "readback"};
    EXPECT_EQ(plan.executed_names(), expected);
    for (ViewId eye : kEyeViews) {
        const PlannedPass* pass = plan.find_unit("probe", eye);
        ASSERT_NE(pass, nullptr);
        EXPECT_EQ(pass->kind, PassKind::kUnit);
        EXPECT_EQ(pass->name, view_name(eye) + ".probe");
        EXPECT_EQ(plan.reads(*pass), Names{view_name(eye) + ".linear_depth"});
        EXPECT_EQ(plan.writes(*pass), Names{view_name(eye) + ".display"});
        const PlannedPass* tonemap = plan.find(PassKind::kTonemap, eye);
        ASSERT_NE(tonemap, nullptr);
        EXPECT_EQ(tonemap->skipped, "culled: nothing reads " + view_name(eye) + ".display");
    }
}

// SSAO only fed the eyes' colour, which nothing reads now: it goes with the tone mapping. TAA
// stays: its history is kept for the next frames (a persistent image), whatever this one shows.
TEST(PassUnit, SsaoThatOnlyFedTheDisplayIsCulledAndTaaKeepsItsHistory) {
    const FramePlan ssao = plan_frame(options_for(Mode::kStereo, false, true),
                                      showing("probe-view"), PlanDevice{}, with_probe());
    EXPECT_EQ(ssao.find(PassKind::kSsao)->skipped,
              "culled: nothing reads left.ao_scratch, left.ao, right.ao_scratch, right.ao, "
              "left.hdr, right.hdr");
    EXPECT_TRUE(ssao.runs(PassKind::kForward, ViewId::kLeft));
    const FramePlan taa = plan_frame(options_for(Mode::kStereo, true, false), showing("probe-view"),
                                     PlanDevice{}, with_probe());
    EXPECT_TRUE(taa.runs(PassKind::kTaa, ViewId::kLeft));
    EXPECT_FALSE(taa.runs(PassKind::kTonemap, ViewId::kLeft));
}

// Hybrid, shown: C and the composites still run (the eyes' linear depth holds C's beyond m);
// C's own tone mapping feeds its read-back and stays.
TEST(PassUnit, HybridKeepsCAndTheCompositesThatWriteTheDepthItReads) {
    for (const bool conditional : {false, true}) {
        const FramePlan plan = plan_frame(options_for(Mode::kHybrid), showing("probe-view"),
                                          PlanDevice{conditional}, with_probe());
        const Names executed = plan.executed_names();
        for (const char* name : {"mono.forward", "left.composite", "right.composite",
                                 "mono.tonemap", "left.probe", "right.probe"}) {
            EXPECT_NE(std::find(executed.begin(), executed.end(), name), executed.end())
                << name << (conditional ? " predicated" : "");
        }
        const auto at = [&](const std::string& name) {
            return std::find(executed.begin(), executed.end(), name) - executed.begin();
        };
        EXPECT_LT(at("right.composite"), at("left.probe"));
        EXPECT_LT(at("right.probe"), at("readback"));
    }
}

TEST(PassUnit, ItsPlanJsonNamesTheUnitAsTheKind) {
    const FramePlan plan =
        plan_frame(options_for(Mode::kStereo), showing("probe-view"), PlanDevice{}, with_probe());
    JsonWriter j;
    j.begin_object();
    write_plan_json(j, plan, "plan");
    j.end_object();
    EXPECT_NE(j.str().find(R"("pass":"left.probe","kind":"probe","view":"left")"),
              std::string::npos)
        << j.str();
}

TEST(PassUnit, AStepDeclaresExactlyTheResourcesItUses) {
    const FramePlan plan =
        plan_frame(options_for(Mode::kStereo), showing("probe-view"), PlanDevice{}, with_probe());
    const graph::Step& step = plan.find_unit("probe", ViewId::kLeft)->steps.front();
    const auto handle = [&](ViewId view, ImageRole role) {
        return *plan.handle({view, false, role, BufferRole::kDrawLists});
    };
    EXPECT_TRUE(step_declares(step, handle(ViewId::kLeft, ImageRole::kLinearDepth)));
    EXPECT_TRUE(step_declares(step, handle(ViewId::kLeft, ImageRole::kDisplay)));
    EXPECT_FALSE(step_declares(step, handle(ViewId::kLeft, ImageRole::kHdr)));
    EXPECT_FALSE(step_declares(step, handle(ViewId::kRight, ImageRole::kDisplay)));
}

// A unit named like a built-in kind would make two kinds of one name.
TEST(PassUnitDeathTest, AUnitNamedAsABuiltInKindIsRefused) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    PassUnitDeclaration unit = probe();
    unit.name = "tonemap";
    EXPECT_DEATH((void)plan_frame(options_for(Mode::kStereo), PlanFrame{}, PlanDevice{}, {unit}),
                 "programming error.*pass unit 'tonemap' has the name of a built-in kind");
}

// A built-in kind written as a unit goes by its kind's name, or its passes' names and keys would
// not be the kind's.
TEST(PassUnitDeathTest, ABuiltInKindsUnitNamedOtherwiseIsRefused) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    PassUnitDeclaration unit = probe();
    unit.kind = PassKind::kTaa;
    unit.name = "resolve";
    EXPECT_DEATH((void)plan_frame(options_for(Mode::kStereo), PlanFrame{}, PlanDevice{}, {unit}),
                 "programming error.*pass unit 'resolve' is kind 'taa' and must have its name");
}

// TAA is a built-in kind written as a unit (renderer/passes/taa/taa_unit.cpp): its passes come
// from its declaration alone, keep the kind (found, named and keyed as before), run per eye after
// the eyes' SSAO and before their tone mapping, which reads the resolve instead of the HDR image.
TEST(PassUnit, TaaIsAUnitOfItsKindBeforeTheToneMapping) {
    const PlanOptions options = options_for(Mode::kStereo, true, true);
    const FramePlan without_units = plan_frame(options, PlanFrame{}, PlanDevice{}, {});
    EXPECT_EQ(without_units.find(PassKind::kTaa, ViewId::kLeft), nullptr);
    const FramePlan plan = passes::plan_frame(options, PlanFrame{}, PlanDevice{});
    const Names expected = {"culling",  "shadow",    "left.forward", "right.forward", "ssao",
                            "left.taa", "right.taa", "left.tonemap", "right.tonemap", "readback"};
    EXPECT_EQ(plan.executed_names(), expected);
    for (ViewId eye : kEyeViews) {
        const PlannedPass* taa = plan.find(PassKind::kTaa, eye);
        ASSERT_NE(taa, nullptr);
        EXPECT_EQ(taa->unit, "taa");
        EXPECT_EQ(plan.find_unit("taa", eye), taa);
        const std::string v = view_name(eye);
        EXPECT_EQ(plan.reads(*taa), (Names{v + ".hdr", v + ".velocity", v + ".linear_depth",
                                           v + ".history_previous"}));
        EXPECT_EQ(plan.writes(*taa), Names{v + ".history"});
        EXPECT_EQ(plan.reads(*plan.find(PassKind::kTonemap, eye)), Names{v + ".history"});
    }
}

// The depth histogram is a built-in kind written as a unit too (renderer/passes/depth_histogram/
// depth_histogram_unit.cpp): placed under `--mono-plane auto` only, after the tone mapping and
// right before the read-back, "clear" then "count" over both eyes' final depth into one buffer,
// which the host reads after the frame, so that the pass is never culled.
TEST(PassUnit, TheDepthHistogramIsAUnitWhoseBufferTheHostReads) {
    PlanOptions options = options_for(Mode::kHybrid);
    EXPECT_EQ(
        passes::plan_frame(options, PlanFrame{}, PlanDevice{}).find(PassKind::kDepthHistogram),
        nullptr);
    options.depth_histogram = true;
    EXPECT_EQ(plan_frame(options, PlanFrame{}, PlanDevice{}, {}).find(PassKind::kDepthHistogram),
              nullptr);
    const FramePlan plan = passes::plan_frame(options, PlanFrame{}, PlanDevice{});
    const PlannedPass* histogram = plan.find(PassKind::kDepthHistogram);
    ASSERT_NE(histogram, nullptr);
    EXPECT_EQ(histogram->unit, "depth_histogram");
    EXPECT_EQ(histogram->name, "depth_histogram");
    EXPECT_FALSE(histogram->skipped);
    ASSERT_EQ(histogram->steps.size(), 2u);
    EXPECT_EQ(histogram->steps[0].name, "clear");
    EXPECT_EQ(histogram->steps[1].name, "count");
    EXPECT_EQ(plan.reads(*histogram), (Names{"left.linear_depth", "right.linear_depth"}));
    EXPECT_EQ(plan.writes(*histogram), Names{"depth_histogram"});
    const std::uint16_t bins =
        *plan.handle({ViewId::kNone, true, ImageRole::kHdr, BufferRole::kDepthHistogram});
    EXPECT_NE(std::find(plan.exports.begin(), plan.exports.end(),
                        graph::ResourceUse{bins, graph::Use::kHostRead}),
              plan.exports.end());
    const Names executed = plan.executed_names();
    const auto at = std::find(executed.begin(), executed.end(), "depth_histogram");
    ASSERT_NE(at, executed.end());
    EXPECT_EQ(*(at - 1), "mono.tonemap");
    EXPECT_EQ(*(at + 1), "readback");
}

// The tone mapping is a built-in kind written as a unit too (renderer/passes/tonemap/
// tonemap_unit.cpp). Where the plan had the composite write the display image (hybrid without TAA
// and SSAO), it declares its own variant: with GPU predicates it runs only if C had nothing
// (mono-none) and loads the display image it may keep; without, it is left out. Under TAA it
// reads the resolve. Without the registered units a plan has no tone mapping at all.
TEST(PassUnit, TheToneMappingIsAUnitThatDeclaresItsFusedVariant) {
    const PlanFrame drawn;  // something lies beyond m
    EXPECT_EQ(plan_frame(options_for(Mode::kHybrid), drawn, PlanDevice{true}, {})
                  .find(PassKind::kTonemap, ViewId::kLeft),
              nullptr);
    for (const bool conditional : {false, true}) {
        const FramePlan plan =
            passes::plan_frame(options_for(Mode::kHybrid), drawn, PlanDevice{conditional});
        for (ViewId eye : kEyeViews) {
            const std::string v = view_name(eye);
            ASSERT_TRUE(plan.find(PassKind::kComposite, eye)->writes_display);
            const PlannedPass* tonemap = plan.find(PassKind::kTonemap, eye);
            ASSERT_NE(tonemap, nullptr);
            EXPECT_EQ(tonemap->unit, "tonemap");
            if (conditional) {
                EXPECT_FALSE(tonemap->skipped);
                EXPECT_EQ(tonemap->when, GpuPredicate::kMonoNone);
                // The display image is loaded (a blend): read as well as written.
                EXPECT_EQ(plan.reads(*tonemap), (Names{v + ".hdr", v + ".display", "predicates"}));
            } else {
                EXPECT_EQ(tonemap->skipped,
                          "fused into " + v + ".composite: nothing else reads " + v + ".hdr");
            }
            EXPECT_EQ(plan.writes(*tonemap), Names{v + ".display"});
        }
        const PlannedPass* mono = plan.find(PassKind::kTonemap, ViewId::kMono);
        ASSERT_NE(mono, nullptr);
        EXPECT_EQ(plan.reads(*mono), Names{"mono.hdr"});
    }
    const FramePlan taa =
        passes::plan_frame(options_for(Mode::kHybrid, true, false), drawn, PlanDevice{true});
    EXPECT_FALSE(taa.find(PassKind::kComposite, ViewId::kLeft)->writes_display);
    EXPECT_EQ(taa.reads(*taa.find(PassKind::kTonemap, ViewId::kLeft)), Names{"left.history"});
    EXPECT_EQ(taa.find(PassKind::kTonemap, ViewId::kLeft)->when, GpuPredicate::kAlways);
    const FramePlan stereo = passes::plan_frame(options_for(Mode::kStereo), drawn, PlanDevice{});
    EXPECT_EQ(stereo.find(PassKind::kTonemap, ViewId::kMono), nullptr);
    EXPECT_EQ(stereo.reads(*stereo.find(PassKind::kTonemap, ViewId::kRight)), Names{"right.hdr"});
}

// The composite is a built-in kind written as a unit (renderer/passes/composite/
// composite_unit.cpp): per eye in the hybrid modes only, after C's passes, under mono-any with
// predicates, skipped with C. It tone maps (writes_display) exactly where no pass placed after it
// uses the eye's HDR image: a unit before the tone mapping that reads left.hdr keeps the left
// composite a blend into left.hdr, and the right one still fuses.
void place_left_hdr_reader(UnitPlacement& placement) {
    PlannedPass& pass = placement.add_pass(ViewId::kLeft);
    graph::Step& step = pass.steps.emplace_back();
    step.name = "read";
    graph::StepBuilder(step)
        .use(placement.resources().image(ViewId::kLeft, ImageRole::kHdr),
             graph::Use::kSampledFragment)
        .use(placement.resources().image(ViewId::kLeft, ImageRole::kHistory),
             graph::Use::kColorWrite);
}

TEST(PassUnit, TheCompositeFusesOnlyWhereNoLaterPassUsesTheEyesHdrImage) {
    const PlanFrame drawn;
    EXPECT_EQ(plan_frame(options_for(Mode::kHybrid), drawn, PlanDevice{}, {})
                  .find(PassKind::kComposite, ViewId::kLeft),
              nullptr);
    EXPECT_EQ(passes::plan_frame(options_for(Mode::kStereo), drawn, PlanDevice{})
                  .find(PassKind::kComposite, ViewId::kLeft),
              nullptr);
    std::vector<PassUnitDeclaration> units = passes::pass_unit_declarations();
    PassUnitDeclaration reader;
    reader.name = "left_hdr_reader";
    reader.slots = {UnitSlot::kBeforeToneMapping};
    reader.place = &place_left_hdr_reader;
    units.push_back(reader);
    const FramePlan plan = plan_frame(options_for(Mode::kHybrid), drawn, PlanDevice{true}, units);
    const PlannedPass* left = plan.find(PassKind::kComposite, ViewId::kLeft);
    const PlannedPass* right = plan.find(PassKind::kComposite, ViewId::kRight);
    ASSERT_NE(left, nullptr);
    ASSERT_NE(right, nullptr);
    EXPECT_EQ(left->unit, "composite");
    EXPECT_EQ(left->statistics_scope, "left.composite");
    EXPECT_EQ(left->when, GpuPredicate::kMonoAny);
    EXPECT_FALSE(left->writes_display);
    EXPECT_EQ(plan.writes(*left), (Names{"left.hdr", "left.linear_depth"}));
    EXPECT_TRUE(right->writes_display);
    EXPECT_EQ(plan.writes(*right), (Names{"right.linear_depth", "right.display"}));
    EXPECT_EQ(plan.reads(*right), (Names{"mono.hdr", "mono.linear_depth", "right.hdr",
                                         "right.depth", "right.linear_depth", "predicates"}));
    // The left eye's tone mapping is its own pass, reading what the composite blended.
    EXPECT_EQ(plan.find(PassKind::kTonemap, ViewId::kLeft)->when, GpuPredicate::kAlways);
    // No C this frame: both composites are skipped, saying why, and neither fuses.
    const FramePlan skipped =
        plan_frame(options_for(Mode::kHybrid), showing("", true), PlanDevice{true}, units);
    for (ViewId eye : kEyeViews) {
        const PlannedPass* composite = skipped.find(PassKind::kComposite, eye);
        ASSERT_NE(composite, nullptr);
        EXPECT_EQ(composite->skipped, "m >= far: nothing lies beyond the mono plane, no C");
        EXPECT_FALSE(composite->writes_display);
    }
}

// The read-back is a built-in kind written as a unit (renderer/passes/readback/readback_unit.cpp):
// last in every frame, after the depth histogram, one "copy" step of what the renderer was asked
// to read back, each buffer marked as read by the host; the culling's counts always, C's display
// image only in a frame that draws C. Without the registered units a plan has none.
TEST(PassUnit, TheReadBackIsAUnitLastInTheFrameWhoseBuffersTheHostReads) {
    PlanOptions options = options_for(Mode::kHybrid, false, true);
    options.read_back_depth = true;
    options.read_back_ao = true;
    options.read_back_draw_lists = true;
    options.depth_histogram = true;
    EXPECT_EQ(plan_frame(options, PlanFrame{}, PlanDevice{}, {}).find(PassKind::kReadback),
              nullptr);
    const FramePlan plan = passes::plan_frame(options, PlanFrame{}, PlanDevice{});
    ASSERT_FALSE(plan.passes.empty());
    const PlannedPass& readback = plan.passes.back();
    EXPECT_EQ(&readback, plan.find(PassKind::kReadback));
    EXPECT_EQ(readback.unit, "readback");
    EXPECT_EQ(readback.name, "readback");
    ASSERT_EQ(readback.steps.size(), 1u);
    EXPECT_EQ(readback.steps[0].name, "copy");
    EXPECT_EQ(plan.passes[plan.passes.size() - 2].kind, PassKind::kDepthHistogram);
    EXPECT_EQ(plan.reads(readback), (Names{"left.display", "left.linear_depth", "left.ao",
                                           "right.display", "right.linear_depth", "right.ao",
                                           "mono.display", "predicates", "draw_lists"}));
    const Names written = {"left.readback",  "left.depth_readback",  "left.ao_readback",
                           "right.readback", "right.depth_readback", "right.ao_readback",
                           "mono.readback",  "counts_readback",      "lists_readback"};
    EXPECT_EQ(plan.writes(readback), written);
    for (const std::string& name : written) {
        const auto exported = std::find_if(
            plan.exports.begin(), plan.exports.end(), [&](const graph::ResourceUse& e) {
                return plan.resources[e.resource].name == name && e.use == graph::Use::kHostRead;
            });
        EXPECT_NE(exported, plan.exports.end()) << name;
    }
    // No C this frame, and only what is always read back: the counts.
    PlanOptions least = options_for(Mode::kHybrid);
    least.read_back = false;
    const FramePlan skipped = passes::plan_frame(least, showing("", true), PlanDevice{});
    const PlannedPass* counts = skipped.find(PassKind::kReadback);
    ASSERT_NE(counts, nullptr);
    EXPECT_EQ(skipped.reads(*counts), Names{"predicates"});
    EXPECT_EQ(skipped.writes(*counts), Names{"counts_readback"});
    EXPECT_FALSE(counts->skipped);
}

// The shadow map is a built-in kind written as a unit (renderer/passes/shadow/shadow_unit.cpp):
// right after the culling, before every forward pass, which reads the map it writes; skipped,
// saying why, in a frame whose light region is the one the map holds. Without the registered units
// a plan has none.
TEST(PassUnit, TheShadowMapIsAUnitAfterTheCullingThatTheForwardPassesRead) {
    EXPECT_EQ(plan_frame(options_for(Mode::kHybrid), PlanFrame{}, PlanDevice{}, {})
                  .find(PassKind::kShadow),
              nullptr);
    for (Mode mode : {Mode::kStereo, Mode::kHybrid}) {
        const FramePlan plan = passes::plan_frame(options_for(mode), PlanFrame{}, PlanDevice{});
        ASSERT_GE(plan.passes.size(), 3u);
        EXPECT_EQ(plan.passes[0].kind, PassKind::kCulling);
        const PlannedPass& shadow = plan.passes[1];
        EXPECT_EQ(&shadow, plan.find(PassKind::kShadow));
        EXPECT_EQ(shadow.unit, "shadow");
        EXPECT_EQ(shadow.name, "shadow");
        EXPECT_FALSE(shadow.skipped);
        EXPECT_TRUE(plan.reads(shadow).empty());
        EXPECT_EQ(plan.writes(shadow), Names{"shadow_map"});
        for (const PlannedPass& pass : plan.passes) {
            if (pass.kind != PassKind::kForward) continue;
            const Names reads = plan.reads(pass);
            EXPECT_NE(std::find(reads.begin(), reads.end(), "shadow_map"), reads.end())
                << pass.name;
        }
    }
    PlanFrame reused;
    reused.shadow_needed = false;
    const FramePlan plan = passes::plan_frame(options_for(Mode::kStereo), reused, PlanDevice{});
    EXPECT_EQ(plan.find(PassKind::kShadow)->skipped,
              "light region unchanged: the shadow map is reused");
}

// The index of the pass named `name` in the plan (a failure, and past the end, if none).
std::size_t position(const FramePlan& plan, const std::string& name) {
    for (std::size_t p = 0; p < plan.passes.size(); ++p) {
        if (plan.passes[p].name == name) return p;
    }
    ADD_FAILURE() << "no pass " << name;
    return plan.passes.size();
}

Names step_names(const PlannedPass& pass) {
    Names names;
    for (const graph::Step& step : pass.steps) names.push_back(step.name);
    return names;
}

// SSAO is one unit placed at two slots: C's pass after C's forward pass and before the
// composite that maps C's colour into the eyes, the eyes' pass once every surface is drawn
// (after the blended chunks) and before TAA; its steps are the unit's one table.
TEST(PassUnit, SsaoIsOneUnitAtTwoSlotsCsBeforeTheCompositeTheEyesBeforeTaa) {
    PlanOptions options = options_for(Mode::kHybrid, true, true);
    options.blended = true;
    const FramePlan hybrid = passes::plan_frame(options, PlanFrame{}, PlanDevice{true, true});
    const PlannedPass* mono = hybrid.find(PassKind::kSsao, ViewId::kMono);
    const PlannedPass* eyes = hybrid.find(PassKind::kSsao);
    ASSERT_NE(mono, nullptr);
    ASSERT_NE(eyes, nullptr);
    EXPECT_EQ(mono->unit, "ssao");
    EXPECT_EQ(mono->name, "mono.ssao");
    EXPECT_EQ(eyes->name, "ssao");
    EXPECT_LT(position(hybrid, "mono.forward"), position(hybrid, "mono.ssao"));
    EXPECT_LT(position(hybrid, "mono.ssao"), position(hybrid, "left.composite"));
    EXPECT_LT(position(hybrid, "right.transparency"), position(hybrid, "ssao"));
    EXPECT_LT(position(hybrid, "ssao"), position(hybrid, "left.taa"));
    // C's runs only when C has something (the GPU's word), and its steps are C's alone.
    EXPECT_EQ(mono->when, GpuPredicate::kMonoAny);
    EXPECT_EQ(step_names(*mono), (Names{"estimate", "filter-x", "filter-y", "apply"}));
    // Each step reads the GPU's word; the compute steps write the scratch and AO images, the
    // apply blends into the HDR image (a read and a write).
    EXPECT_EQ(hybrid.reads(*mono),
              (Names{"mono.linear_depth", "predicates", "mono.ao", "mono.hdr"}));
    EXPECT_EQ(hybrid.writes(*mono), (Names{"mono.ao_scratch", "mono.ao", "mono.hdr"}));
    // The per-eye form: three steps per eye, then the applies, depth-tested in hybrid.
    EXPECT_EQ(step_names(*eyes),
              (Names{"left.estimate", "left.filter-x", "left.filter-y", "right.estimate",
                     "right.filter-x", "right.filter-y", "left.apply", "right.apply"}));
    const Names apply_reads = [&] {
        PlannedPass apply;
        apply.steps = {eyes->steps[6]};
        return hybrid.reads(apply);
    }();
    EXPECT_EQ(apply_reads, (Names{"left.ao", "left.hdr", "left.depth"}));

    // Stereo: no pass of C's; the eyes' applies are not depth-tested; the stereo-consistent
    // form binds both eyes' images in each of its eight dispatches.
    options = options_for(Mode::kStereo, false, true);
    options.ssao_stereo = true;
    const FramePlan stereo = passes::plan_frame(options, PlanFrame{}, PlanDevice{});
    EXPECT_EQ(stereo.find(PassKind::kSsao, ViewId::kMono), nullptr);
    const PlannedPass& consistent = *stereo.find(PassKind::kSsao);
    EXPECT_EQ(step_names(consistent),
              (Names{"visibility-left", "visibility-right", "estimate-left", "estimate-right",
                     "filter-x-left", "filter-x-right", "filter-y-left", "filter-y-right",
                     "left.apply", "right.apply"}));
    for (std::size_t s = 0; s < 8; ++s) {
        PlannedPass one;
        one.steps = {consistent.steps[s]};
        EXPECT_EQ(stereo.writes(one),
                  (Names{"left.ao_scratch", "left.ao", "right.ao_scratch", "right.ao"}))
            << consistent.steps[s].name;
    }
    PlannedPass apply;
    apply.steps = {consistent.steps[9]};
    EXPECT_EQ(stereo.reads(apply), (Names{"right.ao", "right.hdr"}));

    // A hybrid frame without C skips C's pass for the reason every pass of C's gives.
    PlanFrame no_mono;
    no_mono.mono_skipped = true;
    const FramePlan skipped =
        passes::plan_frame(options_for(Mode::kHybrid, false, true), no_mono, PlanDevice{});
    EXPECT_EQ(skipped.find(PassKind::kSsao, ViewId::kMono)->skipped,
              skipped.find(PassKind::kForward, ViewId::kMono)->skipped);
    EXPECT_TRUE(skipped.find(PassKind::kSsao, ViewId::kMono)->skipped.has_value());
}

// The recorder finds each declared step in the unit's table by name: the names are unique
// across C's and both eyes' forms, and each names the step it was made from.
TEST(PassUnit, EverySsaoStepNameFindsItsOwnStep) {
    std::set<std::string> names;
    std::vector<passes::ssao::Step> all = passes::ssao::mono_steps();
    for (bool stereo : {false, true}) {
        for (const passes::ssao::Step& step : passes::ssao::eye_steps(stereo)) {
            all.push_back(step);
        }
    }
    for (const passes::ssao::Step& step : all) {
        names.insert(step.name);
        const passes::ssao::Step* found = passes::ssao::step_named(step.name);
        ASSERT_NE(found, nullptr) << step.name;
        EXPECT_EQ(found->dispatch, step.dispatch) << step.name;
        EXPECT_EQ(found->self, step.self) << step.name;
        EXPECT_EQ(found->other, step.other) << step.name;
    }
    // 4 of C's, 6 + 2 per eye, 8 stereo (their applies are the per-eye form's).
    EXPECT_EQ(names.size(), 4u + 8u + 8u);
    EXPECT_EQ(passes::ssao::step_named("left.taa"), nullptr);
    // Sect. 3.2: only the right eye reprojects the left's estimate.
    EXPECT_EQ(passes::ssao::step_named("estimate-right")->dispatch,
              passes::ssao::Dispatch::kStereoReprojectedEstimate);
    EXPECT_EQ(passes::ssao::step_named("estimate-left")->dispatch,
              passes::ssao::Dispatch::kStereoEstimate);
}

// The merged depth pyramid is a unit between the eyes' forward passes and C's; whether it runs,
// whether the occlusion culling runs and whether C masks its hidden pixels is one rule
// (depth_test_skip_reason), checked here against the cases written out by hand.
TEST(PassUnit, TheDepthPyramidIsAUnitBetweenTheEyesAndCWithTheOneDepthTestRule) {
    EXPECT_EQ(passes::plan_frame(options_for(Mode::kStereo), PlanFrame{}, PlanDevice{})
                  .find(PassKind::kDepthPyramid),
              nullptr);
    const FramePlan hybrid =
        passes::plan_frame(options_for(Mode::kHybrid), PlanFrame{}, PlanDevice{true, true});
    const PlannedPass& pyramid = *hybrid.find(PassKind::kDepthPyramid);
    EXPECT_EQ(pyramid.unit, "depth_pyramid");
    EXPECT_FALSE(pyramid.skipped);
    EXPECT_EQ(pyramid.when, GpuPredicate::kMonoDepthTested);
    EXPECT_EQ(position(hybrid, "right.forward") + 1, position(hybrid, "depth_pyramid"));
    EXPECT_EQ(position(hybrid, "depth_pyramid") + 1, position(hybrid, "occlusion_culling"));
    EXPECT_EQ(step_names(pyramid), (Names{"blocks", "merge", "reduce"}));
    EXPECT_TRUE(pyramid.steps[2].repeats);
    EXPECT_EQ(hybrid.reads(pyramid),
              (Names{"left.depth", "right.depth", "predicates", "pyramid_blocks"}));
    EXPECT_EQ(hybrid.writes(pyramid), (Names{"pyramid_blocks", "merged_depth"}));

    struct Case {
        Mode mode;
        bool mono_skipped;
        DebugView debug;
        MonoCulling culling;
        const char* reason;  // nullptr: depth-tested
    };
    const Case cases[] = {
        {Mode::kHybrid, false, DebugView::kNone, MonoCulling::kOcclusionCull, nullptr},
        {Mode::kHybrid, false, DebugView::kNone, MonoCulling::kDiscard, nullptr},
        {Mode::kHybrid, true, DebugView::kNone, MonoCulling::kOcclusionCull,
         "m >= far: nothing lies beyond the mono plane, no C"},
        {Mode::kHybridFarfield, false, DebugView::kNone, MonoCulling::kOcclusionCull,
         "hybrid-farfield: C is frustum-culled only"},
        {Mode::kHybrid, false, DebugView::kMonoOnly, MonoCulling::kOcclusionCull,
         "debug view mono-only: C's whole image"},
        {Mode::kHybrid, false, DebugView::kNone, MonoCulling::kNoOpt,
         "variant no-opt: no depth test"},
    };
    for (const Case& c : cases) {
        PlanFrame frame;
        frame.mono_skipped = c.mono_skipped;
        frame.debug = c.debug;
        frame.mono_culling = c.culling;
        const FramePlan plan = passes::plan_frame(options_for(c.mode), frame, PlanDevice{});
        const std::optional<std::string> reason = plan.find(PassKind::kDepthPyramid)->skipped;
        SCOPED_TRACE(c.reason ? c.reason : "depth-tested");
        EXPECT_EQ(reason, c.reason ? std::optional<std::string>(c.reason) : std::nullopt);
        EXPECT_EQ(depth_test_skip_reason(options_for(c.mode), frame), reason);
        // C masks its hidden pixels exactly when the pyramid is built.
        const PlannedPass& mono = *plan.find(PassKind::kForward, ViewId::kMono);
        const bool masks = std::any_of(mono.draws.begin(), mono.draws.end(), [](const auto& d) {
            return d.step == DrawStep::kMaskHidden;
        });
        EXPECT_EQ(masks, !reason.has_value());
        // The occlusion culling gives the same reason, or its own for the variant discard.
        const std::optional<std::string> occlusion =
            plan.find(PassKind::kOcclusionCulling)->skipped;
        if (c.culling == MonoCulling::kDiscard) {
            EXPECT_EQ(occlusion, "variant discard: C's hidden chunks are still drawn");
        } else {
            EXPECT_EQ(occlusion, reason);
        }
    }
}

// The chunk culling is a unit first in every frame; the occlusion culling a unit after the
// pyramid it reads and before C's forward pass, which draws the list it rewrites.
TEST(PassUnit, TheCullingIsFirstAndTheOcclusionCullingFollowsThePyramid) {
    for (Mode mode : {Mode::kStereo, Mode::kHybrid}) {
        const FramePlan plan = passes::plan_frame(options_for(mode), PlanFrame{}, PlanDevice{});
        const PlannedPass& culling = plan.passes.front();
        EXPECT_EQ(culling.kind, PassKind::kCulling);
        EXPECT_EQ(culling.unit, "culling");
        EXPECT_EQ(step_names(culling), Names{"frustum"});
        EXPECT_TRUE(plan.reads(culling).empty());
        EXPECT_EQ(plan.writes(culling), (Names{"draw_lists", "predicates", "lod_state"}));
        EXPECT_EQ(plan.find(PassKind::kOcclusionCulling) != nullptr, mode != Mode::kStereo);
    }
    const FramePlan hybrid =
        passes::plan_frame(options_for(Mode::kHybrid), PlanFrame{}, PlanDevice{true, true});
    const PlannedPass& occlusion = *hybrid.find(PassKind::kOcclusionCulling);
    EXPECT_EQ(occlusion.unit, "occlusion_culling");
    EXPECT_EQ(occlusion.when, GpuPredicate::kMonoDepthTested);
    EXPECT_EQ(position(hybrid, "depth_pyramid") + 1, position(hybrid, "occlusion_culling"));
    EXPECT_EQ(position(hybrid, "occlusion_culling") + 1, position(hybrid, "mono.forward"));
    EXPECT_EQ(hybrid.reads(occlusion), (Names{"merged_depth", "lod_state", "predicates"}));
    EXPECT_EQ(hybrid.writes(occlusion), (Names{"draw_lists", "predicates"}));
}

// The forward passes are one unit at two slots (the eyes' after the shadow map, C's after the
// occlusion culling), the blended chunks after the composite another; with them every pass of
// every plan is a unit's, planned from its declaration.
TEST(PassUnit, TheForwardPassesAndTheTransparencyAreUnitsAndSoIsEveryPass) {
    PlanOptions options = options_for(Mode::kHybrid, true, true);
    options.blended = true;
    const FramePlan hybrid = passes::plan_frame(options, PlanFrame{}, PlanDevice{true, true});
    for (const char* name : {"left.forward", "right.forward", "mono.forward"}) {
        const PlannedPass& pass = hybrid.passes[position(hybrid, name)];
        EXPECT_EQ(pass.unit, "forward") << name;
        EXPECT_EQ(pass.kind, PassKind::kForward) << name;
        EXPECT_EQ(step_names(pass), Names{"draw"}) << name;
    }
    EXPECT_EQ(position(hybrid, "shadow") + 1, position(hybrid, "left.forward"));
    EXPECT_EQ(position(hybrid, "occlusion_culling") + 1, position(hybrid, "mono.forward"));
    EXPECT_EQ(position(hybrid, "mono.forward") + 1, position(hybrid, "mono.ssao"));
    // C's forward pass masks first, and reads the pyramid only then.
    const PlannedPass& mono = *hybrid.find(PassKind::kForward, ViewId::kMono);
    ASSERT_FALSE(mono.draws.empty());
    EXPECT_EQ(mono.draws.front().step, DrawStep::kMaskHidden);
    const Names mono_reads = hybrid.reads(mono);
    EXPECT_NE(std::find(mono_reads.begin(), mono_reads.end(), "merged_depth"), mono_reads.end());
    const Names left_reads = hybrid.reads(*hybrid.find(PassKind::kForward, ViewId::kLeft));
    EXPECT_EQ(std::find(left_reads.begin(), left_reads.end(), "merged_depth"), left_reads.end());
    for (const char* name : {"left.transparency", "right.transparency"}) {
        const PlannedPass& pass = hybrid.passes[position(hybrid, name)];
        EXPECT_EQ(pass.unit, "transparency") << name;
        EXPECT_GT(position(hybrid, name), position(hybrid, "right.composite")) << name;
        EXPECT_LT(position(hybrid, name), position(hybrid, "ssao")) << name;
    }
    EXPECT_EQ(hybrid.reads(*hybrid.find(PassKind::kTransparency, ViewId::kLeft)),
              (Names{"draw_lists", "predicates", "shadow_map", "left.linear_depth", "left.hdr"}));
    // Without C the eyes draw their blended chunks themselves.
    PlanFrame no_mono;
    no_mono.mono_skipped = true;
    EXPECT_EQ(passes::plan_frame(options, no_mono, PlanDevice{})
                  .find(PassKind::kTransparency, ViewId::kLeft),
              nullptr);

    // Single-pass stereo: one pass of both eyes, whose step declares both eyes' targets.
    PlanOptions single = options_for(Mode::kStereo, false, false);
    single.stereo_pass = StereoPass::kMultiview;
    const FramePlan stereo = passes::plan_frame(single, PlanFrame{}, PlanDevice{});
    const PlannedPass& eyes = *stereo.find(PassKind::kForward, ViewId::kEyes);
    EXPECT_EQ(eyes.name, "eyes.forward");
    EXPECT_EQ(stereo.find(PassKind::kForward, ViewId::kLeft), nullptr);
    EXPECT_EQ(stereo.writes(eyes), (Names{"left.depth", "left.hdr", "left.linear_depth",
                                          "right.depth", "right.hdr", "right.linear_depth"}));

    for (const FramePlan* plan : {&hybrid, &stereo}) {
        for (const PlannedPass& pass : plan->passes) {
            EXPECT_FALSE(pass.unit.empty()) << pass.name;
            EXPECT_NE(pass.kind, PassKind::kUnit) << pass.name;
        }
    }
}

}  // namespace
}  // namespace monoplane::plan
