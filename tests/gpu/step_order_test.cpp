// The executor checks, in every build type, that each pass records the steps its plan declares,
// by name and in order: a step recorded out of order, one too many or one left out stops the
// program (a programming error, common/programming_error.h) naming the pass and both steps. The
// passes are made up here, two steps over one buffer, so the test shows the check and not a pass.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "renderer/graph/frame_graph.h"
#include "renderer/plan/pass_steps.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/graph_harness.h"

namespace monoplane::testing {
namespace {

using Names = std::vector<std::string>;

// Records one frame of a pass declaring "clear" then "count" (the depth histogram's steps), whose
// recorder begins the steps `recorded` in that order.
void record_pass_naming(vk_core::Context& ctx, const Names& recorded) {
    GraphHarness harness;
    const graph::BufferHandle bins = harness.resources().shared(plan::BufferRole::kDepthHistogram);
    std::vector<graph::Step> steps(2);
    steps[0].name = "clear";
    graph::StepBuilder(steps[0]).use(bins, graph::Use::kTransferDst);
    steps[1].name = "count";
    graph::StepBuilder(steps[1]).use(bins, graph::Use::kStorageWrite);
    harness.add_pass(plan::PassKind::kDepthHistogram, "depth_histogram", std::move(steps),
                     [&](const vk::raii::CommandBuffer& cmd, passes::StepSync& sync) {
                         for (const std::string& step : recorded) sync.next(cmd, step);
                     });
    harness.host_reads(bins);
    ctx.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) { harness.record(cmd); });
}

class StepOrder : public GpuTest {
  protected:
    void SetUp() override {
        // The child of a death test starts afresh (its own device), rather than forking a process
        // whose driver threads it would not have.
        GTEST_FLAG_SET(death_test_style, "threadsafe");
        GpuTest::SetUp();
    }
};

TEST_F(StepOrder, ThePlansStepsInItsOrderAreRecorded) {
    record_pass_naming(ctx(), {"clear", "count"});
}

TEST_F(StepOrder, AStepRecordedOutOfOrderStopsTheProgramNamingBoth) {
    EXPECT_DEATH(record_pass_naming(ctx(), {"count", "clear"}),
                 "programming error.*depth_histogram recorded step 'count' where its plan "
                 "declares 'clear'");
}

TEST_F(StepOrder, AStepOfAnotherNameStopsTheProgram) {
    EXPECT_DEATH(record_pass_naming(ctx(), {"clear", "estimate"}),
                 "depth_histogram recorded step 'estimate' where its plan declares 'count'");
}

TEST_F(StepOrder, AStepTooManyStopsTheProgram) {
    EXPECT_DEATH(record_pass_naming(ctx(), {"clear", "count", "count"}),
                 "depth_histogram recorded step 'count' after the last step its plan declares");
}

TEST_F(StepOrder, AStepLeftOutStopsTheProgram) {
    EXPECT_DEATH(record_pass_naming(ctx(), {"clear"}),
                 "depth_histogram recorded fewer steps than its plan declares");
}

}  // namespace
}  // namespace monoplane::testing
