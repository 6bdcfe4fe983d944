// Memory aliasing of transient resources (renderer/graph/transient_aliasing.h), without a GPU:
// the lifetimes a frame gives its resources, the greedy assignment of resources to shared
// memory over several plans, and the barriers the compile step adds when a resource takes memory
// over from another (renderer/graph/frame_graph.h). Every expected value is worked out by hand
// here from the rules in those headers.
#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/graph/frame_graph.h"
#include "renderer/graph/transient_aliasing.h"

namespace monoplane::graph {
namespace {

constexpr Stage kDepthTests = Stage::kEarlyFragmentTests | Stage::kLateFragmentTests;
constexpr Access kDepthReadWrite =
    Access::kDepthStencilAttachmentRead | Access::kDepthStencilAttachmentWrite;

// Passes of one step each over one table.
class Frame {
  public:
    ImageHandle image(const std::string& name, Lifetime lifetime = Lifetime::kTransient) {
        return table.image(name, lifetime);
    }
    // A pass of one step with the given uses.
    void pass(const std::string& name, std::vector<ResourceUse> uses, bool runs = true,
              bool repeats = false) {
        Step step;
        step.name = "step";
        step.uses = std::move(uses);
        step.repeats = repeats;
        steps.push_back({step});
        names.push_back(name);
        running.push_back(runs);
    }
    std::vector<GraphPass> passes() const {
        std::vector<GraphPass> out;
        for (std::size_t p = 0; p < steps.size(); ++p) {
            out.push_back({names[p], &steps[p], running[p]});
        }
        return out;
    }

    ResourceTable table;
    std::vector<ResourceUse> exports;

  private:
    std::deque<std::vector<Step>> steps;
    std::vector<std::string> names;
    std::vector<bool> running;
};

ResourceUse use(ImageHandle image, Use how) {
    return {image.index, how};
}

TEST(FrameLifetimes, FirstAndLastStepOverThePassesThatRun) {
    Frame f;
    const ImageHandle a = f.image("a");
    const ImageHandle b = f.image("b");
    const ImageHandle c = f.image("c");
    const ImageHandle history = f.image("history", Lifetime::kPersistent);
    const ImageHandle unused = f.image("unused");
    f.pass("p0", {use(a, Use::kColorWrite)});
    f.pass("skipped", {use(unused, Use::kColorWrite), use(a, Use::kSampledFragment)}, false);
    f.pass("p1", {use(a, Use::kSampledFragment), use(b, Use::kStorageWrite)}, true, true);
    f.pass("p2", {use(b, Use::kSampledFragment), use(c, Use::kColorWrite),
                  use(history, Use::kColorWrite)});
    f.exports.push_back(use(c, Use::kTransferSrc));
    const std::vector<FrameLifetime> lifetimes = frame_lifetimes(f.table, f.passes(), f.exports);
    ASSERT_EQ(lifetimes.size(), 5u);
    // Steps counted: p0 = 0, p1 = 1 (repeated, still one), p2 = 2; the skipped pass none.
    EXPECT_EQ(lifetimes[a.index], (FrameLifetime{Interval{0, 1}, true}));
    EXPECT_EQ(lifetimes[b.index], (FrameLifetime{Interval{1, 2}, true}));
    EXPECT_EQ(lifetimes[c.index], (FrameLifetime{Interval{2, 2}, false}));        // exported
    EXPECT_EQ(lifetimes[history.index], (FrameLifetime{Interval{2, 2}, false}));  // persistent
    EXPECT_EQ(lifetimes[unused.index], (FrameLifetime{std::nullopt, true}));
}

FrameLifetime used(std::uint32_t first, std::uint32_t last) {
    return {Interval{first, last}, true};
}
const FrameLifetime kUnused{std::nullopt, true};

TEST(PlanAliasing, LargestFirstEachJoinsTheFirstGroupItNeverOverlaps) {
    // One plan: a [0, 1], b [1, 2], c [2, 3], d [4, 4].
    const std::vector<AliasCandidate> candidates = {
        {100, ~0u, {used(0, 1)}},  // a
        {80, ~0u, {used(1, 2)}},   // b
        {60, ~0u, {used(2, 3)}},   // c
        {120, ~0u, {used(4, 4)}},  // d
    };
    // Order d, a, b, c: d opens group 0; a does not overlap d: group 0; b overlaps a: group 1;
    // c overlaps neither d nor a: group 0.
    const std::vector<AliasGroup> groups = plan_aliasing(candidates);
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0], (AliasGroup{{3, 0, 2}, 120, ~0u}));
    EXPECT_EQ(groups[1], (AliasGroup{{1}, 80, ~0u}));
    EXPECT_EQ(aliased_bytes(groups), 200u);
    EXPECT_EQ(unaliased_bytes(candidates), 360u);
}

TEST(PlanAliasing, APairMustBeDisjointInEveryPlan) {
    // a and b are disjoint in plan 0 and overlap in plan 1; a and c are disjoint in plan 0 and c
    // is unused in plan 1 (no constraint there).
    const std::vector<AliasCandidate> candidates = {
        {100, ~0u, {used(0, 1), used(0, 2)}},  // a
        {100, ~0u, {used(2, 3), used(2, 3)}},  // b
        {50, ~0u, {used(3, 3), kUnused}},      // c
    };
    EXPECT_FALSE(may_share(candidates[0], candidates[1]));
    EXPECT_TRUE(may_share(candidates[0], candidates[2]));
    const std::vector<AliasGroup> groups = plan_aliasing(candidates);
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0].members, (std::vector<std::size_t>{0, 2}));
    EXPECT_EQ(groups[1].members, (std::vector<std::size_t>{1}));
}

TEST(PlanAliasing, NothingSharesWithAResourceAPlanExportsOrKeeps) {
    // b is exported (or persistent) in plan 1, though disjoint from a there and unused in plan 0.
    const FrameLifetime exported{Interval{3, 3}, false};
    const std::vector<AliasCandidate> candidates = {
        {100, ~0u, {used(0, 1), used(0, 1)}},
        {100, ~0u, {kUnused, exported}},
    };
    EXPECT_FALSE(may_share(candidates[0], candidates[1]));
    EXPECT_EQ(plan_aliasing(candidates).size(), 2u);
    // A plan that does not use it does not count: not used, nothing to keep.
    const std::vector<AliasCandidate> unused_there = {
        {100, ~0u, {used(0, 1), kUnused}},
        {100, ~0u, {used(2, 2), FrameLifetime{std::nullopt, false}}},
    };
    EXPECT_TRUE(may_share(unused_there[0], unused_there[1]));
}

TEST(PlanAliasing, MembersShareAMemoryTypeTheyAllAllow) {
    const std::vector<AliasCandidate> candidates = {
        {100, 0b0011, {used(0, 0)}},
        {90, 0b0100, {used(1, 1)}},  // no type in common with the first
        {80, 0b0110, {used(2, 2)}},  // common with the first in bit 1, joins it
    };
    const std::vector<AliasGroup> groups = plan_aliasing(candidates);
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0], (AliasGroup{{0, 2}, 100, 0b0010}));
    EXPECT_EQ(groups[1], (AliasGroup{{1}, 90, 0b0100}));
}

TEST(PlanAliasing, RefusesLifetimesOfDifferentPlans) {
    const std::vector<AliasCandidate> candidates = {
        {100, ~0u, {used(0, 0)}},
        {100, ~0u, {used(1, 1), used(1, 1)}},
    };
    EXPECT_DEATH(plan_aliasing(candidates), "candidates with lifetimes in 1 and 2 plans");
    EXPECT_TRUE(plan_aliasing({}).empty());
}

// a (a depth image written, then sampled by compute) and b (a colour image written, then sampled
// by a fragment shader) share memory 0.
struct SharedPair {
    Frame f;
    ImageHandle a = f.image("a");
    ImageHandle b = f.image("b");
    SharedPair() {
        f.pass("draw-a", {use(a, Use::kDepthWrite)});
        f.pass("read-a", {use(a, Use::kDepthSampledCompute)});
        f.pass("draw-b", {use(b, Use::kColorWrite)});
        f.pass("read-b", {use(b, Use::kSampledFragment)});
    }
    Aliasing aliasing(MemoryHolder initial = {}) const { return {{0, 0}, {initial}}; }
};

TEST(CompileAliasing, TheTakerWaitsForTheHolderAndStartsFromUndefined) {
    SharedPair s;
    const CompiledFrame frame =
        compile(s.f.table, s.f.passes(), {}, std::vector<ResourceState>(2), s.aliasing());
    // draw-a: nothing held the memory before; a's first barrier only sets its layout.
    EXPECT_EQ(
        frame.steps[0][0].before,
        (std::vector<Barrier>{{s.a.index, Stage::kNone, Access::kNone, kDepthTests, kDepthReadWrite,
                               Layout::kUndefined, Layout::kDepthAttachment, false}}));
    // draw-b takes over from a, last sampled by compute (a read: an execution dependency, no
    // access to make available); b's layout starts undefined.
    EXPECT_EQ(frame.steps[2][0].before,
              (std::vector<Barrier>{{s.b.index, Stage::kComputeShader, Access::kNone,
                                     Stage::kColorAttachmentOutput, Access::kColorAttachmentWrite,
                                     Layout::kUndefined, Layout::kColorAttachment, true}}));
    EXPECT_EQ(frame.final_holders, (std::vector<std::int32_t>{s.b.index}));
}

TEST(CompileAliasing, TheNextFrameFirstUserWaitsForTheLastFramesLastHolder) {
    SharedPair s;
    const CompiledFrame first =
        compile(s.f.table, s.f.passes(), {}, std::vector<ResourceState>(2), s.aliasing());
    const CompiledFrame second = compile(s.f.table, s.f.passes(), {}, first.final_states,
                                         s.aliasing({first.final_holders[0], {}}));
    // a takes over from b, last sampled by a fragment shader, instead of continuing from its own
    // depth-read-only layout.
    EXPECT_EQ(second.steps[0][0].before,
              (std::vector<Barrier>{{s.a.index, Stage::kFragmentShader, Access::kNone, kDepthTests,
                                     kDepthReadWrite, Layout::kUndefined, Layout::kDepthAttachment,
                                     true}}));
    EXPECT_EQ(second.steps[2][0].before, first.steps[2][0].before);
    // Without aliasing, a would wait for its own compute reads and keep its layout's contents.
    const CompiledFrame alone = compile(s.f.table, s.f.passes(), {}, first.final_states);
    EXPECT_EQ(alone.steps[0][0].before[0].src_stages, Stage::kComputeShader);
    EXPECT_EQ(alone.steps[0][0].before[0].old_layout, Layout::kDepthReadOnly);
    EXPECT_TRUE(alone.final_holders.empty());
}

TEST(CompileAliasing, AHolderOfAnotherPlanIsWaitedForByItsState) {
    SharedPair s;
    ResourceState other;  // a resource this plan lacks, last written by a copy
    other.layout = Layout::kTransferDst;
    other.write_stages = Stage::kTransfer;
    other.write_access = Access::kTransferWrite;
    const CompiledFrame frame = compile(s.f.table, s.f.passes(), {}, std::vector<ResourceState>(2),
                                        s.aliasing({-1, other}));
    EXPECT_EQ(frame.steps[0][0].before,
              (std::vector<Barrier>{{s.a.index, Stage::kTransfer, Access::kTransferWrite,
                                     kDepthTests, kDepthReadWrite, Layout::kUndefined,
                                     Layout::kDepthAttachment, true}}));
}

TEST(CompileAliasing, TheHolderOfTheLastFrameKeepsItsOwnState) {
    SharedPair s;
    const CompiledFrame first =
        compile(s.f.table, s.f.passes(), {}, std::vector<ResourceState>(2), s.aliasing());
    // As if a had been the last to use the memory: its first barrier is the one it would have
    // without aliasing.
    const CompiledFrame again = compile(s.f.table, s.f.passes(), {}, first.final_states,
                                        s.aliasing({static_cast<std::int32_t>(s.a.index), {}}));
    const CompiledFrame alone = compile(s.f.table, s.f.passes(), {}, first.final_states);
    EXPECT_EQ(again.steps[0][0].before, alone.steps[0][0].before);
}

TEST(CompileAliasing, RefusesInterleavedExportedAndPersistentSharers) {
    {
        Frame f;
        const ImageHandle a = f.image("a");
        const ImageHandle b = f.image("b");
        f.pass("draw-a", {use(a, Use::kColorWrite)});
        f.pass("draw-b", {use(b, Use::kColorWrite)});
        f.pass("read-a", {use(a, Use::kSampledFragment)});
        const Aliasing aliasing{{0, 0}, {MemoryHolder{}}};
        EXPECT_DEATH(compile(f.table, f.passes(), {}, std::vector<ResourceState>(2), aliasing),
                     "uses a after b, which shares its memory, took it over");
    }
    {
        Frame f;
        const ImageHandle a = f.image("a");
        f.pass("draw-a", {use(a, Use::kColorWrite)});
        f.exports.push_back(use(a, Use::kTransferSrc));
        const Aliasing aliasing{{0}, {MemoryHolder{}}};
        EXPECT_DEATH(
            compile(f.table, f.passes(), f.exports, std::vector<ResourceState>(1), aliasing),
            "a is exported and shares memory");
    }
    {
        Frame f;
        const ImageHandle a = f.image("a", Lifetime::kPersistent);
        f.pass("draw-a", {use(a, Use::kColorWrite)});
        const Aliasing aliasing{{0}, {MemoryHolder{}}};
        EXPECT_DEATH(compile(f.table, f.passes(), {}, std::vector<ResourceState>(1), aliasing),
                     "a is persistent and shares memory");
    }
}

}  // namespace
}  // namespace monoplane::graph
