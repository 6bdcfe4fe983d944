// A pass unit's recorder reaches only what its current step declared (renderer/modes/
// unit_recording.h): an image its step declared is handed over, any other stops the program
// naming the pass, the step and the image, in every build type; buffers likewise. The unit is the
// test's own, one step reading an eye's linear depth and writing its display image and the depth
// histogram's buffer; no device is needed, since the check comes before anything is touched.
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "renderer/modes/unit_recording.h"
#include "renderer/plan/pass_unit.h"

namespace monoplane::modes {
namespace {

void place_probe(plan::UnitPlacement& placement) {
    plan::PlannedPass& pass = placement.add_pass(plan::ViewId::kLeft);
    graph::Step& step = pass.steps.emplace_back();
    step.name = "draw";
    graph::StepBuilder(step)
        .use(placement.resources().image(plan::ViewId::kLeft, plan::ImageRole::kLinearDepth),
             graph::Use::kSampledFragment)
        .use(placement.resources().image(plan::ViewId::kLeft, plan::ImageRole::kDisplay),
             graph::Use::kColorWrite)
        .use(placement.resources().shared(plan::BufferRole::kDepthHistogram),
             graph::Use::kStorageWrite);
}

class NoSync final : public passes::StepSync {
  public:
    void next(const vk::raii::CommandBuffer&, std::string_view) override {}
};

// What the image resolver was asked for: it throws this instead of handing an image over.
struct Asked {
    plan::ResourceKey key;
};

class UnitRecordingCheck : public ::testing::Test {
  protected:
    UnitRecordingCheck() {
        plan::PassUnitDeclaration probe;
        probe.name = "probe";
        probe.place = &place_probe;
        plan_ =
            plan::plan_frame(plan::PlanOptions{}, plan::PlanFrame{}, plan::PlanDevice{}, {probe});
    }

    // The recording of left.probe, whose resolvers throw what they are asked for.
    std::unique_ptr<passes::UnitRecording> recording() {
        const plan::PlannedPass* pass = plan_.find_unit("probe", plan::ViewId::kLeft);
        EXPECT_NE(pass, nullptr);
        UnitResolvers resolvers;
        resolvers.image = [](const plan::ResourceKey& key) -> const vk_core::Image& {
            throw Asked{key};
        };
        resolvers.buffer = [](const plan::ResourceKey& key) -> const vk_core::Buffer& {
            throw Asked{key};
        };
        resolvers.predicate = [](plan::GpuPredicate) { return std::optional<passes::Predicate>(); };
        return make_unit_recording(cmd_, plan_, *pass, sync_, passes::UnitFrameValues{},
                                   std::move(resolvers));
    }

    // Asks the recording of left.probe for `role` of `view`.
    void ask(plan::ViewId view, plan::ImageRole role) { (void)recording()->image(view, role); }
    void ask(plan::ViewId view, plan::BufferRole role) { (void)recording()->buffer(view, role); }

    plan::FramePlan plan_;
    vk::raii::CommandBuffer cmd_{nullptr};
    NoSync sync_;
};

TEST_F(UnitRecordingCheck, AnImageItsStepDeclaredIsHandedOver) {
    for (plan::ImageRole role : {plan::ImageRole::kLinearDepth, plan::ImageRole::kDisplay}) {
        try {
            ask(plan::ViewId::kLeft, role);
            ADD_FAILURE() << "the resolver was not asked";
        } catch (const Asked& asked) {
            EXPECT_EQ(asked.key, (plan::ResourceKey{plan::ViewId::kLeft, false, role,
                                                    plan::BufferRole::kDrawLists}));
        }
    }
}

TEST_F(UnitRecordingCheck, ItSaysWhichImagesItsStepDeclares) {
    const std::unique_ptr<passes::UnitRecording> r = recording();
    EXPECT_TRUE(r->declares(plan::ViewId::kLeft, plan::ImageRole::kLinearDepth));
    EXPECT_TRUE(r->declares(plan::ViewId::kLeft, plan::ImageRole::kDisplay));
    EXPECT_FALSE(r->declares(plan::ViewId::kLeft, plan::ImageRole::kHdr));
    EXPECT_FALSE(r->declares(plan::ViewId::kRight, plan::ImageRole::kDisplay));
    EXPECT_FALSE(r->declares(plan::ViewId::kLeft, plan::ImageRole::kHistory));
}

TEST_F(UnitRecordingCheck, AnImageOfThePlanItsStepDidNotDeclareStopsTheProgram) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(ask(plan::ViewId::kLeft, plan::ImageRole::kHdr),
                 "programming error.*left.probe touched left.hdr in step 'draw', which does "
                 "not declare it");
    EXPECT_DEATH(ask(plan::ViewId::kRight, plan::ImageRole::kDisplay),
                 "left.probe touched right.display in step 'draw'");
}

TEST_F(UnitRecordingCheck, ABufferItsStepDeclaredIsHandedOverAndAnyOtherStopsTheProgram) {
    try {
        ask(plan::ViewId::kNone, plan::BufferRole::kDepthHistogram);
        ADD_FAILURE() << "the resolver was not asked";
    } catch (const Asked& asked) {
        EXPECT_EQ(asked.key, (plan::ResourceKey{plan::ViewId::kNone, true, plan::ImageRole::kHdr,
                                                plan::BufferRole::kDepthHistogram}));
    }
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(ask(plan::ViewId::kLeft, plan::BufferRole::kReadback),
                 "programming error.*left.probe touched left.readback in step 'draw', which "
                 "does not declare it");
}

// Single-pass stereo's two-layer image stands for both eyes' images: only a step that declares
// both may have it. The probe declares the left eye's alone.
TEST_F(UnitRecordingCheck, BothEyesImageNeedsBothEyesDeclared) {
    EXPECT_FALSE(recording()->declares(plan::ViewId::kEyes, plan::ImageRole::kLinearDepth));
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(ask(plan::ViewId::kEyes, plan::ImageRole::kLinearDepth),
                 "left.probe touched right.linear_depth in step 'draw'");
}

// A view's chunk draws are the draw lists and the predicates: the probe declares neither.
TEST_F(UnitRecordingCheck, ChunkDrawsNeedTheDrawListsDeclared) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH((void)recording()->chunk_draws(passes::CullView::kLeft),
                 "left.probe touched draw_lists in step 'draw'");
}

TEST_F(UnitRecordingCheck, AnImageNoPassOfTheFrameUsesStopsTheProgram) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(ask(plan::ViewId::kLeft, plan::ImageRole::kHistory),
                 "left.probe touched left.history in step 'draw'");
}

}  // namespace
}  // namespace monoplane::modes
