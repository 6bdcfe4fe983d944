// A pass unit's recorder reaches only what its current step declared (renderer/modes/
// unit_recording.h): an image its step declared is handed over, any other stops the program
// naming the pass, the step and the image, in every build type. The unit is the test's own, one
// step reading an eye's linear depth and writing its display image; no device is needed, since
// the check comes before any image is touched.
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
             graph::Use::kColorWrite);
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

    // Asks the recording of left.probe for `role` of `view`.
    void ask(plan::ViewId view, plan::ImageRole role) {
        const plan::PlannedPass* pass = plan_.find_unit("probe", plan::ViewId::kLeft);
        ASSERT_NE(pass, nullptr);
        const std::unique_ptr<passes::UnitRecording> recording = make_unit_recording(
            cmd_, plan_, *pass, sync_, passes::UnitFrameValues{},
            [](const plan::ResourceKey& key) -> const vk_core::Image& { throw Asked{key}; },
            [](plan::GpuPredicate) { return std::optional<passes::Predicate>(); });
        (void)recording->image(view, role);
    }

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

TEST_F(UnitRecordingCheck, AnImageOfThePlanItsStepDidNotDeclareStopsTheProgram) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(ask(plan::ViewId::kLeft, plan::ImageRole::kHdr),
                 "programming error.*left.probe touched left.hdr in step 'draw', which does "
                 "not declare it");
    EXPECT_DEATH(ask(plan::ViewId::kRight, plan::ImageRole::kDisplay),
                 "left.probe touched right.display in step 'draw'");
}

TEST_F(UnitRecordingCheck, AnImageNoPassOfTheFrameUsesStopsTheProgram) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(ask(plan::ViewId::kLeft, plan::ImageRole::kHistory),
                 "left.probe touched left.history in step 'draw'");
}

}  // namespace
}  // namespace monoplane::modes
