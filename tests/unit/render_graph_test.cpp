// The render graph's compiled barriers (renderer/graph/frame_graph.h), without a GPU.
//
// First the compile step on small graphs written here, every expected barrier worked out by hand
// from the Vulkan synchronisation rules: a read after a write needs the write made available (its
// stages and accesses in the barrier's first scope) and visible to the reader (the reader's stages
// and accesses in the second); a write after a read needs only an execution dependency on the
// readers' stages; a layout transition happens between a barrier's two scopes, its writes are
// available automatically, and a later barrier whose first scope shares a stage with the
// transition's second scope chains after it (an execution dependency chain).
//
// Then every mode's frame plan (renderer/plan/frame_plan.h), compiled and replayed through a small
// hazard checker written here from those rules alone (it tracks each resource's layout, its last
// write and where that write is available and visible, and the reads since, per pipeline stage):
// it must find nothing in the compiled frames, and must find a hazard once any one barrier of a
// compiled frame is deleted (which shows the checker can fail). Last, the culling from the
// dataflow.
//
// Canted displays (a headset whose displays are rotated outwards) change the eyes' projections
// only: PlanOptions, PlanFrame and PlanDevice have no input for them, so the plans and barriers
// below are a canted headset's too, and nothing is tested separately for them.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "renderer/graph/frame_graph.h"
#include "renderer/graph/resource_use.h"
#include "renderer/graph/sync_scope.h"
#include "renderer/passes/pass_unit_declarations.h"
#include "renderer/plan/frame_plan.h"
#include "renderer/plan/frame_resources.h"
#include "renderer/plan/render_choices.h"

namespace monoplane::graph {

// gtest's printer for barriers in failure messages (resource index, scopes, layouts).
void PrintTo(const Barrier& b, std::ostream* os) {
    *os << "#" << b.resource << " " << stage_names(b.src_stages) << "/"
        << access_names(b.src_access) << " -> " << stage_names(b.dst_stages) << "/"
        << access_names(b.dst_access) << ", " << layout_name(b.old_layout) << " -> "
        << layout_name(b.new_layout);
}

namespace {

using Barriers = std::vector<Barrier>;
using Problems = std::vector<std::string>;

constexpr Stage kNoStage = Stage::kNone;
constexpr Stage kColorOutput = Stage::kColorAttachmentOutput;
constexpr Stage kFragment = Stage::kFragmentShader;
constexpr Stage kCompute = Stage::kComputeShader;
constexpr Stage kDepthTests = Stage::kEarlyFragmentTests | Stage::kLateFragmentTests;
// A draw's indirect parameters are read in the draw-indirect stage, and its shaders read the
// lists as storage (the vertex shader the instance's chunk, the fragment shader the routing view's
// colours).
constexpr Stage kIndirect = Stage::kDrawIndirect | Stage::kVertexShader | Stage::kFragmentShader;
constexpr Access kNoAccess = Access::kNone;
constexpr Access kSampled = Access::kShaderSampledRead;
constexpr Access kStorageReadWrite = Access::kShaderStorageRead | Access::kShaderStorageWrite;
constexpr Access kDepthReadWrite =
    Access::kDepthStencilAttachmentRead | Access::kDepthStencilAttachmentWrite;

// A hand-made graph: passes of one step each, resources in one table.
class TestGraph {
  public:
    ImageHandle image(const std::string& name, Lifetime lifetime = Lifetime::kTransient) {
        return table_.image(name, lifetime);
    }
    BufferHandle buffer(const std::string& name, Lifetime lifetime = Lifetime::kTransient) {
        return table_.buffer(name, lifetime);
    }
    // Adds a pass of one step; the builder adds the step's uses.
    StepBuilder pass(const std::string& name, bool repeats = false) {
        names_.push_back(name);
        runs_.push_back(true);
        Step& step = steps_.emplace_back().emplace_back();
        step.name = "step";
        step.repeats = repeats;
        return StepBuilder(step);
    }
    void skip(std::size_t pass) { runs_.at(pass) = false; }

    std::vector<GraphPass> passes() const {
        std::vector<GraphPass> passes;
        for (std::size_t p = 0; p < steps_.size(); ++p) {
            passes.push_back({names_[p], &steps_[p], runs_[p]});
        }
        return passes;
    }
    std::vector<ResourceState> fresh() const { return std::vector<ResourceState>(table_.size()); }
    CompiledFrame compile(const std::vector<ResourceUse>& exports = {}) const {
        return graph::compile(table_, passes(), exports, fresh());
    }
    CompiledFrame compile_from(const std::vector<ResourceState>& initial,
                               const std::vector<ResourceUse>& exports = {}) const {
        return graph::compile(table_, passes(), exports, initial);
    }
    std::vector<bool> needed(const std::vector<ResourceUse>& exports) const {
        return needed_passes(table_, passes(), exports);
    }
    const ResourceTable& table() const { return table_; }

  private:
    ResourceTable table_;
    std::deque<std::vector<Step>> steps_;  // a deque: the builders keep references to steps
    std::vector<std::string> names_;
    std::vector<bool> runs_;
};

// The barriers before the first (only) step of a pass.
const Barriers& before(const CompiledFrame& frame, std::size_t pass) {
    return frame.steps.at(pass).at(0).before;
}

Barrier barrier(std::uint16_t resource, Stage src, Access src_access, Stage dst, Access dst_access,
                Layout old_layout = Layout::kUndefined, Layout new_layout = Layout::kUndefined) {
    return {resource, src, src_access, dst, dst_access, old_layout, new_layout};
}

// Every use's (stages, accesses, layout) as the Vulkan specification names them for what the use
// does: the checker below relies on this table, so it is checked against the specification first.
TEST(UseScopes, EachUseStandsForTheStagesAccessesAndLayoutOfWhatItDoes) {
    const auto expect = [](Use use, Stage stages, Access access, Layout layout, bool writes) {
        const UseScope scope = use_scope(use);
        EXPECT_EQ(scope.stages, stages) << use_name(use);
        EXPECT_EQ(scope.access, access) << use_name(use);
        EXPECT_EQ(scope.layout, layout) << use_name(use);
        EXPECT_EQ(scope.writes, writes) << use_name(use);
    };
    const Access color_rw = Access::kColorAttachmentRead | Access::kColorAttachmentWrite;
    const Stage shaders = kFragment | kCompute;
    expect(Use::kColorWrite, kColorOutput, Access::kColorAttachmentWrite, Layout::kColorAttachment,
           true);
    expect(Use::kColorBlend, kColorOutput, color_rw, Layout::kColorAttachment, true);
    expect(Use::kDepthWrite, kDepthTests, kDepthReadWrite, Layout::kDepthAttachment, true);
    expect(Use::kDepthTest, kDepthTests, Access::kDepthStencilAttachmentRead,
           Layout::kDepthAttachment, false);
    expect(Use::kDepthSampledCompute, kCompute, kSampled, Layout::kDepthReadOnly, false);
    expect(Use::kSampledFragment, kFragment, kSampled, Layout::kShaderReadOnly, false);
    expect(Use::kSampledCompute, kCompute, kSampled, Layout::kShaderReadOnly, false);
    expect(Use::kSampledAny, shaders, kSampled, Layout::kShaderReadOnly, false);
    expect(Use::kGeneralSampled, shaders, kSampled, Layout::kGeneral, false);
    expect(Use::kStorageRead, kCompute, Access::kShaderStorageRead, Layout::kGeneral, false);
    expect(Use::kStorageWrite, kCompute, kStorageReadWrite, Layout::kGeneral, true);
    expect(Use::kTransferSrc, Stage::kTransfer, Access::kTransferRead, Layout::kTransferSrc, false);
    expect(Use::kTransferDst, Stage::kTransfer, Access::kTransferWrite, Layout::kTransferDst, true);
    expect(Use::kIndirectArgs, kIndirect, Access::kIndirectCommandRead | Access::kShaderStorageRead,
           Layout::kUndefined, false);
    expect(Use::kConditional, Stage::kConditionalRendering, Access::kConditionalRenderingRead,
           Layout::kUndefined, false);
    expect(Use::kHostRead, Stage::kHost, Access::kHostRead, Layout::kUndefined, false);
}

TEST(GraphCompile, ColourWriteThenFragmentSampleIsOneTransition) {
    TestGraph g;
    const ImageHandle hdr = g.image("hdr");
    g.pass("draw").use(hdr, Use::kColorWrite);
    g.pass("sample").use(hdr, Use::kSampledFragment);
    const CompiledFrame frame = g.compile();
    // First use: nothing earlier to wait for; the undefined contents go to the attachment layout.
    EXPECT_EQ(before(frame, 0), Barriers{barrier(hdr.index, kNoStage, kNoAccess, kColorOutput,
                                                 Access::kColorAttachmentWrite, Layout::kUndefined,
                                                 Layout::kColorAttachment)});
    // Read after write: the attachment write made available and visible to the fragment shader's
    // sampled reads, and the image moved into the layout sampling needs.
    EXPECT_EQ(before(frame, 1),
              Barriers{barrier(hdr.index, kColorOutput, Access::kColorAttachmentWrite, kFragment,
                               kSampled, Layout::kColorAttachment, Layout::kShaderReadOnly)});
    EXPECT_TRUE(frame.final_barriers.empty());
    EXPECT_EQ(frame.final_states.at(hdr.index).layout, Layout::kShaderReadOnly);
}

TEST(GraphCompile, SecondReaderInTheSameStageNeedsNoBarrier) {
    TestGraph g;
    const ImageHandle hdr = g.image("hdr");
    g.pass("draw").use(hdr, Use::kColorWrite);
    g.pass("left").use(hdr, Use::kSampledFragment);
    g.pass("right").use(hdr, Use::kSampledFragment);
    const CompiledFrame frame = g.compile();
    EXPECT_EQ(before(frame, 1).size(), 1u);
    // The write is already visible to fragment-shader sampled reads; reads do not race reads.
    EXPECT_TRUE(before(frame, 2).empty());
}

TEST(GraphCompile, ReaderInAnotherStageGetsAVisibilityBarrierWithoutALayoutChange) {
    TestGraph g;
    const ImageHandle hdr = g.image("hdr");
    g.pass("draw").use(hdr, Use::kColorWrite);
    g.pass("fragment").use(hdr, Use::kSampledFragment);
    g.pass("compute").use(hdr, Use::kSampledCompute);
    g.pass("compute-again").use(hdr, Use::kSampledCompute);
    const CompiledFrame frame = g.compile();
    // The colour write was made available by the fragment reader's barrier, and its layout
    // transition happened before the fragment stage (that barrier's second scope). A barrier whose
    // first scope is the fragment stage chains after both; the compute shader then only needs the
    // write made visible: no source access, no layout change.
    EXPECT_EQ(before(frame, 2),
              Barriers{barrier(hdr.index, kFragment, kNoAccess, kCompute, kSampled,
                               Layout::kShaderReadOnly, Layout::kShaderReadOnly)});
    EXPECT_TRUE(before(frame, 3).empty());
}

TEST(GraphCompile, WriteAfterReadWaitsForEveryReadersStage) {
    TestGraph g;
    const ImageHandle hdr = g.image("hdr");
    const BufferHandle lists = g.buffer("lists");
    g.pass("draw").use(hdr, Use::kColorWrite).use(lists, Use::kStorageWrite);
    g.pass("fragment").use(hdr, Use::kSampledFragment).use(lists, Use::kIndirectArgs);
    g.pass("compute").use(hdr, Use::kSampledCompute);
    g.pass("blend").use(hdr, Use::kColorBlend).use(lists, Use::kStorageWrite);
    const CompiledFrame frame = g.compile();
    // The blend must not start before both readers are done (an execution dependency); the write
    // they read was made available before them, so no source access; the contents are kept.
    ASSERT_EQ(before(frame, 3).size(), 2u);
    EXPECT_EQ(before(frame, 3)[0],
              barrier(hdr.index, kFragment | kCompute, kNoAccess, kColorOutput,
                      Access::kColorAttachmentRead | Access::kColorAttachmentWrite,
                      Layout::kShaderReadOnly, Layout::kColorAttachment));
    // The buffer: the draws' reads (draw-indirect and shader stages) and the first compute write
    // come before the second. (The first write was made available already, so whether the source
    // access repeats it is free: it is not asserted.)
    const Barrier& buffer = before(frame, 3)[1];
    EXPECT_EQ(buffer.resource, lists.index);
    EXPECT_EQ(buffer.src_stages, kCompute | kIndirect);
    EXPECT_EQ(buffer.dst_stages, kCompute);
    EXPECT_EQ(buffer.dst_access, kStorageReadWrite);
    EXPECT_EQ(buffer.old_layout, Layout::kUndefined);
    EXPECT_EQ(buffer.new_layout, Layout::kUndefined);
}

TEST(GraphCompile, OverwritingAReadImageWaitsForTheReadersAndMayDiscard) {
    TestGraph g;
    const ImageHandle display = g.image("display");
    g.pass("tonemap").use(display, Use::kColorWrite);
    g.pass("copy").use(display, Use::kTransferSrc);
    g.pass("tonemap-again").use(display, Use::kColorWrite);
    const CompiledFrame frame = g.compile();
    ASSERT_EQ(before(frame, 2).size(), 1u);
    const Barrier& b = before(frame, 2)[0];
    EXPECT_EQ(b.src_stages, Stage::kTransfer);
    EXPECT_EQ(b.src_access, kNoAccess);
    EXPECT_EQ(b.dst_stages, kColorOutput);
    EXPECT_EQ(b.dst_access, Access::kColorAttachmentWrite);
    // A plain colour write reads nothing: the old contents may be kept or discarded.
    EXPECT_TRUE(b.old_layout == Layout::kTransferSrc || b.old_layout == Layout::kUndefined)
        << layout_name(b.old_layout);
    EXPECT_EQ(b.new_layout, Layout::kColorAttachment);
}

TEST(GraphCompile, WriteAfterWriteMakesTheFirstWriteAvailableToTheSecond) {
    TestGraph g;
    const ImageHandle storage = g.image("storage");
    const ImageHandle hdr = g.image("hdr");
    const ImageHandle depth = g.image("depth");
    g.pass("first")
        .use(storage, Use::kStorageWrite)
        .use(hdr, Use::kColorWrite)
        .use(depth, Use::kDepthWrite);
    g.pass("second")
        .use(storage, Use::kStorageWrite)
        .use(hdr, Use::kColorBlend)
        .use(depth, Use::kDepthWrite);
    const CompiledFrame frame = g.compile();
    EXPECT_EQ(
        before(frame, 1),
        (Barriers{
            barrier(storage.index, kCompute, Access::kShaderStorageWrite, kCompute,
                    kStorageReadWrite, Layout::kGeneral, Layout::kGeneral),
            barrier(hdr.index, kColorOutput, Access::kColorAttachmentWrite, kColorOutput,
                    Access::kColorAttachmentRead | Access::kColorAttachmentWrite,
                    Layout::kColorAttachment, Layout::kColorAttachment),
            barrier(depth.index, kDepthTests, Access::kDepthStencilAttachmentWrite, kDepthTests,
                    kDepthReadWrite, Layout::kDepthAttachment, Layout::kDepthAttachment)}));
}

TEST(GraphCompile, RepeatedStepWaitsForItsPreviousRecording) {
    TestGraph g;
    const ImageHandle depth = g.image("depth");
    const ImageHandle pyramid = g.image("pyramid");
    g.pass("draw").use(depth, Use::kDepthWrite);
    g.pass("merge").use(depth, Use::kDepthSampledCompute).use(pyramid, Use::kStorageWrite);
    g.pass("reduce", true).use(pyramid, Use::kStorageWrite).use(depth, Use::kDepthSampledCompute);
    const CompiledFrame frame = g.compile();
    // Each level reads the one the previous dispatch wrote: storage write -> storage read/write.
    const Barrier waw = barrier(pyramid.index, kCompute, Access::kShaderStorageWrite, kCompute,
                                kStorageReadWrite, Layout::kGeneral, Layout::kGeneral);
    EXPECT_EQ(frame.steps.at(2).at(0).before, Barriers{waw});
    EXPECT_EQ(frame.steps.at(2).at(0).between_repeats, Barriers{waw});
    // Steps that do not repeat have nothing between repeats.
    EXPECT_TRUE(frame.steps.at(1).at(0).between_repeats.empty());

    // A repeated step as the first use: a first-use transition, then the same wait between repeats.
    TestGraph first;
    const ImageHandle image = first.image("image");
    first.pass("reduce", true).use(image, Use::kStorageWrite);
    const CompiledFrame only = first.compile();
    EXPECT_EQ(only.steps.at(0).at(0).before,
              Barriers{barrier(image.index, kNoStage, kNoAccess, kCompute, kStorageReadWrite,
                               Layout::kUndefined, Layout::kGeneral)});
    EXPECT_EQ(only.steps.at(0).at(0).between_repeats,
              Barriers{barrier(image.index, kCompute, Access::kShaderStorageWrite, kCompute,
                               kStorageReadWrite, Layout::kGeneral, Layout::kGeneral)});
}

TEST(GraphCompile, BuffersNeverGetLayouts) {
    TestGraph g;
    const BufferHandle words = g.buffer("words");
    const BufferHandle copy = g.buffer("copy");
    g.pass("clear").use(words, Use::kTransferDst);
    g.pass("cull").use(words, Use::kStorageWrite);
    g.pass("draw").use(words, Use::kIndirectArgs).use(words, Use::kConditional);
    g.pass("readback").use(words, Use::kTransferSrc).use(copy, Use::kTransferDst);
    const CompiledFrame frame = g.compile({{copy.index, Use::kHostRead}});
    // A buffer's first use waits for nothing and has no layout to leave: no barrier at all.
    EXPECT_TRUE(before(frame, 0).empty());
    EXPECT_EQ(before(frame, 1),
              Barriers{barrier(words.index, Stage::kTransfer, Access::kTransferWrite, kCompute,
                               kStorageReadWrite)});
    // Both reads of one step in one barrier: indirect commands, the draws' shaders' storage reads
    // of the draw lists, and the conditional-rendering predicate.
    EXPECT_EQ(before(frame, 2),
              Barriers{barrier(words.index, kCompute, Access::kShaderStorageWrite,
                               kIndirect | Stage::kConditionalRendering,
                               Access::kIndirectCommandRead | Access::kShaderStorageRead |
                                   Access::kConditionalRenderingRead)});
    EXPECT_EQ(before(frame, 3), Barriers{barrier(words.index, kCompute, Access::kShaderStorageWrite,
                                                 Stage::kTransfer, Access::kTransferRead)});
    // The host reads the copy after the frame: the transfer write made visible to the host.
    EXPECT_EQ(frame.final_barriers,
              Barriers{barrier(copy.index, Stage::kTransfer, Access::kTransferWrite, Stage::kHost,
                               Access::kHostRead)});
    for (const auto& pass : frame.steps) {
        for (const CompiledStep& step : pass) {
            for (const Barrier& b : step.before) {
                EXPECT_EQ(b.old_layout, Layout::kUndefined);
                EXPECT_EQ(b.new_layout, Layout::kUndefined);
            }
        }
    }
}

// What a previous frame left a persistent image in is where this frame starts.
TEST(GraphCompile, InitialStateOfThePreviousFrameIsHonoured) {
    TestGraph g;
    const ImageHandle history = g.image("history", Lifetime::kPersistent);
    g.pass("resolve").use(history, Use::kSampledFragment);
    g.pass("compute").use(history, Use::kSampledCompute);
    // Left by the previous frame's fragment-shader reads after its transition to shader-read-only.
    std::vector<ResourceState> sampled = g.fresh();
    sampled[history.index] = {
        Layout::kShaderReadOnly, kFragment, kNoAccess, kFragment, kSampled, kFragment};
    const CompiledFrame from_previous = g.compile_from(sampled);
    EXPECT_TRUE(before(from_previous, 0).empty());
    EXPECT_EQ(before(from_previous, 1),
              Barriers{barrier(history.index, kFragment, kNoAccess, kCompute, kSampled,
                               Layout::kShaderReadOnly, Layout::kShaderReadOnly)});
    // The same graph from nothing: a first use from undefined.
    EXPECT_EQ(before(g.compile(), 0),
              Barriers{barrier(history.index, kNoStage, kNoAccess, kFragment, kSampled,
                               Layout::kUndefined, Layout::kShaderReadOnly)});
    // Left with a colour write nobody has waited for: this frame's reader waits for it.
    std::vector<ResourceState> written = g.fresh();
    written[history.index] = {Layout::kColorAttachment, kColorOutput,
                              Access::kColorAttachmentWrite};
    EXPECT_EQ(
        before(g.compile_from(written), 0),
        Barriers{barrier(history.index, kColorOutput, Access::kColorAttachmentWrite, kFragment,
                         kSampled, Layout::kColorAttachment, Layout::kShaderReadOnly)});
}

TEST(GraphCompile, FinalStatesCarryAPersistentImageIntoTheNextFrame) {
    TestGraph first;
    const ImageHandle shadow = first.image("shadow", Lifetime::kPersistent);
    first.pass("draw").use(shadow, Use::kDepthWrite);
    first.pass("forward").use(shadow, Use::kSampledFragment);
    const CompiledFrame frame1 = first.compile();
    EXPECT_EQ(frame1.final_states.at(shadow.index).layout, Layout::kShaderReadOnly);

    // The next frame reuses the map (no draw) and later draws it again.
    TestGraph second;
    const ImageHandle reused = second.image("shadow", Lifetime::kPersistent);
    second.pass("forward").use(reused, Use::kSampledFragment);
    second.pass("draw").use(reused, Use::kDepthWrite);
    const CompiledFrame frame2 = second.compile_from(frame1.final_states);
    // Already sampled in this layout by the fragment shader: nothing to do.
    EXPECT_TRUE(before(frame2, 0).empty());
    // Drawn again after the reads: waits for them, keeps the contents (a depth write tests).
    EXPECT_EQ(before(frame2, 1),
              Barriers{barrier(reused.index, kFragment, kNoAccess, kDepthTests, kDepthReadWrite,
                               Layout::kShaderReadOnly, Layout::kDepthAttachment)});
}

TEST(GraphCompile, RefusesATransientReadBeforeAnyWrite) {
    TestGraph g;
    const ImageHandle transient = g.image("transient");
    g.pass("sample").use(transient, Use::kSampledFragment);
    EXPECT_DEATH(g.compile(), "reads transient, which no earlier pass of the frame writes");

    TestGraph persistent;
    const ImageHandle kept = persistent.image("kept", Lifetime::kPersistent);
    persistent.pass("sample").use(kept, Use::kSampledFragment);
    EXPECT_NO_THROW(persistent.compile());

    // A write by a pass that does not run produces nothing.
    TestGraph skipped;
    const ImageHandle image = skipped.image("image");
    skipped.pass("draw").use(image, Use::kColorWrite);
    skipped.pass("sample").use(image, Use::kSampledFragment);
    EXPECT_NO_THROW(skipped.compile());
    skipped.skip(0);
    EXPECT_DEATH(skipped.compile(), "reads image, which no earlier pass of the frame writes");

    // A transient export nobody wrote.
    TestGraph exported;
    const BufferHandle buffer = exported.buffer("buffer");
    EXPECT_DEATH(exported.compile({{buffer.index, Use::kHostRead}}), "programming error.*buffer");
}

TEST(GraphCompile, RefusesOneStepUsingAnImageInTwoLayouts) {
    TestGraph colour;
    const ImageHandle hdr = colour.image("hdr");
    colour.pass("draw").use(hdr, Use::kColorWrite).use(hdr, Use::kSampledFragment);
    EXPECT_DEATH(colour.compile(), "uses hdr in two layouts");

    TestGraph depth;
    const ImageHandle d = depth.image("depth");
    depth.pass("draw").use(d, Use::kDepthWrite);
    depth.pass("both").use(d, Use::kDepthTest).use(d, Use::kDepthSampledCompute);
    EXPECT_DEATH(depth.compile(), "uses depth in two layouts");

    // Two uses in one layout are one use.
    TestGraph same;
    const ImageHandle s = same.image("s");
    same.pass("draw").use(s, Use::kColorWrite);
    same.pass("both").use(s, Use::kSampledFragment).use(s, Use::kSampledCompute);
    const CompiledFrame frame = same.compile();
    EXPECT_EQ(
        before(frame, 1),
        Barriers{barrier(s.index, kColorOutput, Access::kColorAttachmentWrite, kFragment | kCompute,
                         kSampled, Layout::kColorAttachment, Layout::kShaderReadOnly)});
}

TEST(GraphCompile, RefusesBufferOnlyUsesOfAnImage) {
    for (Use use : {Use::kIndirectArgs, Use::kConditional, Use::kHostRead}) {
        TestGraph g;
        const ImageHandle image = g.image("image");
        g.pass("draw").use(image, Use::kColorWrite);
        g.pass("misuse").use(image, use);
        EXPECT_DEATH(g.compile(), "is not a use of an image") << use_name(use);
        // As an export too.
        TestGraph e;
        const ImageHandle exported = e.image("image");
        e.pass("draw").use(exported, Use::kColorWrite);
        EXPECT_DEATH(e.compile({{exported.index, use}}), "is not a use of an image")
            << use_name(use);
    }
}

TEST(GraphCompile, RefusesImageUsesOfABuffer) {
    for (Use use : {Use::kColorWrite, Use::kColorBlend, Use::kDepthWrite, Use::kDepthTest,
                    Use::kDepthSampledCompute, Use::kSampledFragment, Use::kSampledCompute,
                    Use::kSampledAny, Use::kGeneralSampled}) {
        TestGraph g;
        const BufferHandle buffer = g.buffer("buffer");
        g.pass("fill").use(buffer, Use::kTransferDst);
        g.pass("misuse").use(buffer, use);
        EXPECT_DEATH(g.compile(), "is not a use of a buffer") << use_name(use);
    }
    // Storage and transfer uses are a buffer's too.
    TestGraph g;
    const BufferHandle buffer = g.buffer("buffer");
    g.pass("fill").use(buffer, Use::kTransferDst);
    g.pass("storage").use(buffer, Use::kStorageWrite).use(buffer, Use::kStorageRead);
    g.pass("copy").use(buffer, Use::kTransferSrc);
    EXPECT_NO_THROW(g.compile());
}

TEST(GraphCompile, RefusesInitialStatesOfTheWrongSize) {
    TestGraph g;
    const ImageHandle image = g.image("image");
    g.image("other");
    g.pass("draw").use(image, Use::kColorWrite);
    EXPECT_NO_THROW(g.compile_from(std::vector<ResourceState>(2)));
    EXPECT_DEATH(g.compile_from(std::vector<ResourceState>(1)), "1 initial states for 2 resources");
    EXPECT_DEATH(g.compile_from(std::vector<ResourceState>(3)), "3 initial states for 2 resources");
    EXPECT_DEATH(g.compile_from({}), "0 initial states for 2 resources");
}

TEST(NeededPasses, AnUnreadImageIsNotNeededAPersistentOrExportedOneIs) {
    TestGraph g;
    const ImageHandle unread = g.image("unread");
    const ImageHandle kept = g.image("kept", Lifetime::kPersistent);
    const ImageHandle shown = g.image("shown");
    const ImageHandle middle = g.image("middle");
    const ImageHandle end = g.image("end");
    g.pass("unread").use(unread, Use::kColorWrite);
    g.pass("persistent").use(kept, Use::kColorWrite);
    g.pass("exported").use(shown, Use::kColorWrite);
    g.pass("producer").use(middle, Use::kColorWrite);
    g.pass("consumer").use(middle, Use::kSampledFragment).use(end, Use::kColorWrite);
    g.pass("reads-only").use(middle, Use::kSampledFragment);
    const std::vector<bool> needed =
        g.needed({{shown.index, Use::kTransferSrc}, {end.index, Use::kSampledFragment}});
    EXPECT_EQ(needed, (std::vector<bool>{false, true, true, true, true, false}));
    // Without the exports only the persistent write is needed.
    EXPECT_EQ(g.needed({}), (std::vector<bool>{false, true, false, false, false, false}));
}

TEST(NeededPasses, AnOverwrittenImageNeedsOnlyItsLastWriterABlendNeedsBoth) {
    for (Use second : {Use::kColorWrite, Use::kColorBlend}) {
        TestGraph g;
        const ImageHandle image = g.image("image");
        const ImageHandle out = g.image("out");
        g.pass("first").use(image, Use::kColorWrite);
        g.pass("second").use(image, second);
        g.pass("reader").use(image, Use::kSampledFragment).use(out, Use::kColorWrite);
        const std::vector<bool> needed = g.needed({{out.index, Use::kTransferSrc}});
        // A plain colour write replaces every texel; a blend reads what the first pass drew.
        EXPECT_EQ(needed, (std::vector<bool>{second == Use::kColorBlend, true, true}))
            << use_name(second);
    }
}

TEST(NeededPasses, AReaderThatDoesNotRunNeedsNothing) {
    TestGraph g;
    const ImageHandle image = g.image("image");
    const ImageHandle out = g.image("out");
    g.pass("producer").use(image, Use::kColorWrite);
    g.pass("consumer").use(image, Use::kSampledFragment).use(out, Use::kColorWrite);
    const std::vector<ResourceUse> exports = {{out.index, Use::kTransferSrc}};
    EXPECT_EQ(g.needed(exports), (std::vector<bool>{true, true}));
    g.skip(1);
    EXPECT_EQ(g.needed(exports), (std::vector<bool>{false, false}));
}

// --- An independent hazard checker -------------------------------------------------------------
//
// It replays a compiled frame: before each step its barriers, then its uses; after the last pass
// the final barriers and the exports. Per resource it tracks the layout, the last write (or layout
// transition), whether that write is available and where it is visible (per stage), and the reads
// since. It knows the rules, not the compile step's model.

constexpr std::size_t kStageCount = 11;  // Stage's bits

Access read_part(Access access) {
    return static_cast<Access>(static_cast<std::uint32_t>(access) &
                               ~static_cast<std::uint32_t>(kWriteAccesses));
}

Stage stage_bit(std::size_t bit) {
    return static_cast<Stage>(1u << bit);
}

// An access later work must be ordered after: its stages, and the stages of later work that the
// barriers so far order after it (an execution dependency and its chains).
struct Ordered {
    Stage stages = Stage::kNone;
    Stage reach = Stage::kNone;
};

// Reports a problem of one resource at one point of the replay; builds strings only when called.
struct Report {
    Problems* problems;
    const std::string* at;
    const std::string* resource;
    void operator()(const std::string& what) const {
        problems->push_back(*at + *resource + " " + what);
    }
};

struct Tracked {
    bool image = true;
    Layout layout = Layout::kUndefined;
    bool fresh = true;           // nothing has accessed it: a first use may wait for nothing
    bool contents_lost = false;  // a transition from undefined discarded contents it had
    bool written = false;        // there is a last write (or transition) to order after
    bool transition = false;     // ... a layout transition: ordered only through its barrier
    Ordered write;
    Access write_access = Access::kNone;
    bool available = false;
    std::array<Access, kStageCount> visible{};  // per stage: the accesses the write is visible to
    std::vector<Ordered> reads;                 // since the last write
};

// A resource's state as a previous frame left it, in the checker's terms.
Tracked tracked_from(const ResourceState& state, bool image) {
    Tracked t;
    t.image = image;
    t.layout = image ? state.layout : Layout::kUndefined;
    t.fresh =
        !any(state.write_stages) && !any(state.read_stages) && state.layout == Layout::kUndefined;
    if (any(state.write_stages)) {
        t.written = true;
        t.write = {state.write_stages, state.visible_stages};
        t.write_access = state.write_access;
        t.available = any(state.visible_stages) || !any(state.write_access);
        for (std::size_t bit = 0; bit < kStageCount; ++bit) {
            if (covers(state.visible_stages, stage_bit(bit))) t.visible[bit] = state.visible_access;
        }
    }
    if (any(state.read_stages)) t.reads.push_back({state.read_stages, Stage::kNone});
    return t;
}

// Whether an access is in a barrier's first synchronisation scope, directly or through a chain.
bool in_first_scope(const Ordered& access, Stage src, bool transition) {
    const bool direct = !transition && any(access.stages) && covers(src, access.stages);
    return direct || any(access.reach & src);
}

void make_visible(Tracked& t, const Barrier& b) {
    for (std::size_t bit = 0; bit < kStageCount; ++bit) {
        if (covers(b.dst_stages, stage_bit(bit))) t.visible[bit] |= b.dst_access;
    }
}

void apply_transition(Tracked& t, const Barrier& b, bool write_ordered,
                      const std::vector<bool>& reads_ordered, const Report& problem) {
    if (b.old_layout != Layout::kUndefined && b.old_layout != t.layout) {
        problem("transitions from " + layout_name(b.old_layout) + " but the image is in " +
                layout_name(t.layout));
    }
    if (t.written && !(write_ordered && t.available)) {
        problem("transitions the layout before the last write is done and available");
    }
    for (bool ordered : reads_ordered) {
        if (!ordered) problem("transitions the layout while an earlier read may still run");
    }
    if (b.old_layout == Layout::kUndefined && t.layout != Layout::kUndefined) {
        t.contents_lost = true;
    }
    t.layout = b.new_layout;
    t.written = true;
    t.transition = true;
    t.write = {Stage::kNone, b.dst_stages};
    t.write_access = Access::kNone;
    t.available = true;  // a transition's writes are made available automatically
    t.visible = {};
    make_visible(t, b);
    t.reads.clear();
}

void apply_barrier(Tracked& t, const Barrier& b, const Report& problem) {
    if (!any(b.dst_stages) || !any(b.dst_access)) problem("has an empty destination scope");
    if (!any(b.src_stages) && !(t.fresh && b.old_layout == Layout::kUndefined)) {
        problem("waits for nothing although the resource was accessed before");
    }
    if (!t.image && (b.old_layout != Layout::kUndefined || b.new_layout != Layout::kUndefined)) {
        problem("gives a buffer a layout");
    }
    const bool write_ordered = t.written && in_first_scope(t.write, b.src_stages, t.transition);
    if (t.written && !t.transition && any(t.write.stages) && covers(b.src_stages, t.write.stages) &&
        covers(b.src_access, t.write_access)) {
        t.available = true;
    }
    std::vector<bool> reads_ordered;
    for (const Ordered& read : t.reads) {
        reads_ordered.push_back(in_first_scope(read, b.src_stages, false));
    }
    if (t.image && b.old_layout != b.new_layout) {
        apply_transition(t, b, write_ordered, reads_ordered, problem);
    } else {
        if (t.image && b.old_layout != t.layout) {
            problem("names layout " + layout_name(b.old_layout) + " but the image is in " +
                    layout_name(t.layout));
        }
        if (write_ordered) {
            t.write.reach |= b.dst_stages;
            if (t.available) make_visible(t, b);
        }
        for (std::size_t r = 0; r < t.reads.size(); ++r) {
            if (reads_ordered[r]) t.reads[r].reach |= b.dst_stages;
        }
    }
    t.fresh = false;
}

// One resource's uses within a step, merged: they happen together. Each use's reads stay with
// its own stages, and the write is the writing uses' alone (a step that writes the predicates in
// a compute shader and reads them for conditional rendering does not write in the latter stage).
struct StepUse {
    std::uint16_t resource = 0;
    Layout layout = Layout::kUndefined;
    Stage stages = Stage::kNone;  // every use's
    Stage write_stages = Stage::kNone;
    Access write_access = Access::kNone;
    std::array<Access, kStageCount> reads_at{};  // per stage: the accesses that read
    bool writes() const { return any(write_stages); }
    // The stages that read and do not also write (a read-modify-write is the write's).
    Stage read_only_stages() const {
        Stage stages_read = Stage::kNone;
        for (std::size_t bit = 0; bit < kStageCount; ++bit) {
            if (any(reads_at[bit]) && !covers(write_stages, stage_bit(bit))) {
                stages_read |= stage_bit(bit);
            }
        }
        return stages_read;
    }
};

std::vector<StepUse> step_uses(const ResourceTable& table, const std::vector<ResourceUse>& uses) {
    std::vector<StepUse> merged;
    for (const ResourceUse& use : uses) {
        const UseScope scope = use_scope(use.use);
        const bool image = table[use.resource].kind == ResourceKind::kImage;
        StepUse* same = nullptr;
        for (StepUse& m : merged) {
            if (m.resource == use.resource) same = &m;
        }
        if (same == nullptr) {
            same = &merged.emplace_back();
            same->resource = use.resource;
            same->layout = image ? scope.layout : Layout::kUndefined;
        }
        same->stages |= scope.stages;
        if (scope.writes) {
            same->write_stages |= scope.stages;
            same->write_access |= scope.access & kWriteAccesses;
        }
        for (std::size_t bit = 0; bit < kStageCount; ++bit) {
            if (covers(scope.stages, stage_bit(bit)))
                same->reads_at[bit] |= read_part(scope.access);
        }
    }
    return merged;
}

void check_use(const Tracked& t, const StepUse& u, const Report& problem) {
    if (t.image && u.layout != t.layout) {
        problem("used in " + layout_name(u.layout) + " while it is in " + layout_name(t.layout));
    }
    const bool reads =
        std::any_of(u.reads_at.begin(), u.reads_at.end(), [](Access a) { return any(a); });
    if (t.image && t.contents_lost && reads) problem("reads contents a transition discarded");
    if (t.written) {
        if (!covers(t.write.reach, u.stages)) {
            problem("is not ordered after the last write");
        } else if (u.writes() && !t.available) {
            problem("writes before the last write was made available");
        }
        for (std::size_t bit = 0; bit < kStageCount; ++bit) {
            if (!covers(t.visible[bit], u.reads_at[bit])) {
                problem("reads in " + stage_names(stage_bit(bit)) +
                        " what the last write left invisible there");
            }
        }
    }
    if (!u.writes()) return;
    for (const Ordered& read : t.reads) {
        if (!covers(read.reach, u.write_stages)) {
            problem("writes while an earlier read may still run");
        }
    }
}

void apply_use(Tracked& t, const StepUse& u) {
    t.fresh = false;
    if (!u.writes()) {
        t.reads.push_back({u.stages, Stage::kNone});
        return;
    }
    t.written = true;
    t.transition = false;
    t.write = {u.write_stages, Stage::kNone};
    t.write_access = u.write_access;
    t.available = false;
    t.visible = {};
    t.reads.clear();
    t.contents_lost = false;
    // The step's reads in other stages: a later write waits for them too.
    if (any(u.read_only_stages())) t.reads.push_back({u.read_only_stages(), Stage::kNone});
}

// A frame as the checker replays it: each pass's steps (empty when it does not run).
struct Replay {
    const ResourceTable* resources = nullptr;
    std::vector<std::string> names;
    std::vector<std::vector<Step>> steps;
    std::vector<bool> runs;
    std::vector<ResourceUse> exports;
};

class HazardChecker {
  public:
    HazardChecker(const Replay& replay, const std::vector<ResourceState>& initial)
        : replay_(replay) {
        for (std::size_t r = 0; r < replay.resources->size(); ++r) {
            const bool image =
                (*replay.resources)[static_cast<std::uint16_t>(r)].kind == ResourceKind::kImage;
            tracked_.push_back(tracked_from(initial.at(r), image));
        }
    }

    Problems run(const CompiledFrame& frame) {
        if (frame.steps.size() != replay_.steps.size()) return {"compiled pass count differs"};
        for (std::size_t p = 0; p < replay_.steps.size(); ++p) {
            const std::vector<Step>& steps = replay_.steps[p];
            const std::size_t count = replay_.runs[p] ? steps.size() : 0;
            if (frame.steps[p].size() != count) {
                problems_.push_back(replay_.names[p] + ": compiled step count differs");
                continue;
            }
            for (std::size_t s = 0; s < count; ++s) {
                const std::string at = replay_.names[p] + "/" + steps[s].name;
                step(at, frame.steps[p][s].before, steps[s].uses);
                if (steps[s].repeats) {
                    step(at + " (repeat)", frame.steps[p][s].between_repeats, steps[s].uses);
                }
            }
        }
        step("exports", frame.final_barriers, replay_.exports);
        return problems_;
    }

  private:
    void step(const std::string& step_name, const Barriers& barriers,
              const std::vector<ResourceUse>& uses) {
        const std::string at_barrier = step_name + ": barrier on ";
        const std::string at_use = step_name + ": ";
        for (const Barrier& b : barriers) {
            apply_barrier(tracked_.at(b.resource), b, report(at_barrier, b.resource));
        }
        const std::vector<StepUse> merged = step_uses(*replay_.resources, uses);
        for (const StepUse& u : merged) {
            check_use(tracked_.at(u.resource), u, report(at_use, u.resource));
        }
        for (const StepUse& u : merged) apply_use(tracked_.at(u.resource), u);
    }

    Report report(const std::string& at, std::uint16_t resource) {
        return {&problems_, &at, &(*replay_.resources)[resource].name};
    }

    const Replay& replay_;
    std::vector<Tracked> tracked_;
    Problems problems_;
};

Problems find_hazards(const Replay& replay, const CompiledFrame& frame,
                      const std::vector<ResourceState>& initial) {
    return HazardChecker(replay, initial).run(frame);
}

bool mentions(const Problems& problems, const std::string& problem) {
    return std::find(problems.begin(), problems.end(), problem) != problems.end();
}

// The checker on hand-made frames: it accepts what the rules allow and reports what they do not.
TEST(HazardChecker, AcceptsAHandWrittenCorrectFrameAndReportsEachMissingPiece) {
    TestGraph g;
    const ImageHandle hdr = g.image("hdr");
    g.pass("draw").use(hdr, Use::kColorWrite);
    g.pass("sample").use(hdr, Use::kSampledFragment);
    g.pass("compute").use(hdr, Use::kSampledCompute);
    Replay replay{&g.table(), {"draw", "sample", "compute"}, {}, {true, true, true}, {}};
    for (const GraphPass& pass : g.passes()) replay.steps.push_back(*pass.steps);
    const auto frame_with = [&](Barriers draw, Barriers sample, Barriers compute) {
        CompiledFrame frame;
        frame.steps = {
            {{std::move(draw), {}}}, {{std::move(sample), {}}}, {{std::move(compute), {}}}};
        return frame;
    };
    const Barrier first =
        barrier(hdr.index, kNoStage, kNoAccess, kColorOutput, Access::kColorAttachmentWrite,
                Layout::kUndefined, Layout::kColorAttachment);
    const Barrier raw = barrier(hdr.index, kColorOutput, Access::kColorAttachmentWrite, kFragment,
                                kSampled, Layout::kColorAttachment, Layout::kShaderReadOnly);
    const Barrier chained = barrier(hdr.index, kFragment, kNoAccess, kCompute, kSampled,
                                    Layout::kShaderReadOnly, Layout::kShaderReadOnly);
    const auto fresh = g.fresh();
    EXPECT_EQ(find_hazards(replay, frame_with({first}, {raw}, {chained}), fresh), Problems{});
    // Waiting for the colour write itself instead is not enough: the layout transition is a later
    // write, ordered only before the fragment stage, which the colour-output stage does not chain
    // with.
    const Barrier direct = barrier(hdr.index, kColorOutput, Access::kColorAttachmentWrite, kCompute,
                                   kSampled, Layout::kShaderReadOnly, Layout::kShaderReadOnly);
    EXPECT_EQ(find_hazards(replay, frame_with({first}, {raw}, {direct}), fresh),
              (Problems{"compute/step: hdr is not ordered after the last write",
                        "compute/step: hdr reads in compute-shader what the last write left "
                        "invisible there"}));
    // Each piece left out is a hazard.
    EXPECT_FALSE(find_hazards(replay, frame_with({}, {raw}, {chained}), fresh).empty());
    EXPECT_FALSE(find_hazards(replay, frame_with({first}, {}, {chained}), fresh).empty());
    EXPECT_FALSE(find_hazards(replay, frame_with({first}, {raw}, {}), fresh).empty());
    // A transition without the write's access: not available, a hazard.
    Barrier unavailable = raw;
    unavailable.src_access = kNoAccess;
    EXPECT_FALSE(
        find_hazards(replay, frame_with({first}, {unavailable}, {chained}), fresh).empty());
    // A barrier with nothing in its destination scope, or waiting for nothing after an access.
    Barrier empty_dst = raw;
    empty_dst.dst_access = kNoAccess;
    EXPECT_TRUE(mentions(find_hazards(replay, frame_with({first}, {empty_dst}, {chained}), fresh),
                         "sample/step: barrier on hdr has an empty destination scope"));
    Barrier waits_for_nothing = chained;
    waits_for_nothing.src_stages = kNoStage;
    EXPECT_TRUE(
        mentions(find_hazards(replay, frame_with({first}, {raw}, {waits_for_nothing}), fresh),
                 "compute/step: barrier on hdr waits for nothing although the resource was "
                 "accessed before"));
    // A chain through a stage the transition did not reach: no chain.
    Barrier broken = chained;
    broken.src_stages = kColorOutput;
    broken.src_access = kNoAccess;
    EXPECT_FALSE(find_hazards(replay, frame_with({first}, {raw}, {broken}), fresh).empty());
}

}  // namespace
}  // namespace monoplane::graph

namespace monoplane::plan {
namespace {

// The frame plan as the renderer plans it: with the registered pass units (TAA among them).
using graph::Access;
using graph::Barrier;
using graph::CompiledFrame;
using graph::Layout;
using graph::ResourceState;
using graph::Stage;
using passes::plan_frame;
using Problems = std::vector<std::string>;

constexpr Stage kDepthTests = Stage::kEarlyFragmentTests | Stage::kLateFragmentTests;
constexpr std::array<ViewId, 2> kEyes = kEyeViews;

// One combination of the plan's inputs.
struct Combination {
    PlanOptions options;
    PlanFrame frame;
    PlanDevice device;

    bool hybrid() const { return options.mode != Mode::kStereo; }
    bool draws_mono() const { return hybrid() && !frame.mono_skipped; }
    // The merged depth pyramid runs (monoplane's hybrid with a depth-tested variant).
    bool pyramid() const {
        return draws_mono() && options.mode == Mode::kHybrid &&
               frame.mono_culling != MonoCulling::kNoOpt && frame.debug != DebugView::kMonoOnly;
    }
    std::string text() const {
        std::ostringstream s;
        s << mode_name(options.mode) << " " << stereo_pass_name(options.stereo_pass) << " "
          << mono_culling_name(frame.mono_culling) << " "
          << anti_aliasing_name(options.anti_aliasing) << " ssao " << options.ssao << " stereo "
          << options.ssao_stereo << " prepass " << options.depth_prepass << " conditional "
          << device.conditional_rendering << " mono_skipped " << frame.mono_skipped << " histogram "
          << options.depth_histogram << " read_back " << options.read_back << " depth/ao/lists "
          << options.read_back_depth << options.read_back_ao << options.read_back_draw_lists
          << " shadow_needed " << frame.shadow_needed << " mono-only "
          << (frame.debug == DebugView::kMonoOnly);
        return s.str();
    }
};

// The on/off inputs of a combination, one bit each.
enum Flag : unsigned {
    kPrepass = 1u << 0,
    kConditional = 1u << 1,
    kMonoSkipped = 1u << 2,
    kHistogram = 1u << 3,
    kReadBack = 1u << 4,
    kReadBackExtras = 1u << 5,  // depth, AO (with SSAO) and draw lists
    kShadowReused = 1u << 6,
    kMonoOnlyView = 1u << 7,
    kFlagCount = 1u << 8,
};

// ssao: 0 off, 1 per eye, 2 stereo-consistent.
Combination combination(Mode mode, StereoPass pass, MonoCulling culling, AntiAliasing aa, int ssao,
                        unsigned flags) {
    Combination c;
    c.options.mode = mode;
    c.options.stereo_pass = pass;
    c.options.anti_aliasing = aa;
    c.options.ssao = ssao != 0;
    c.options.ssao_stereo = ssao == 2;
    c.options.depth_prepass = (flags & kPrepass) != 0;
    c.options.depth_histogram = (flags & kHistogram) != 0;
    c.options.read_back = (flags & kReadBack) != 0;
    c.options.read_back_depth = (flags & kReadBackExtras) != 0;
    c.options.read_back_ao = (flags & kReadBackExtras) != 0 && ssao != 0;  // AO needs SSAO
    c.options.read_back_draw_lists = (flags & kReadBackExtras) != 0;
    c.frame.mono_skipped = (flags & kMonoSkipped) != 0;
    c.frame.mono_culling = culling;
    c.frame.shadow_needed = (flags & kShadowReused) == 0;
    c.frame.debug = (flags & kMonoOnlyView) != 0 ? DebugView::kMonoOnly : DebugView::kNone;
    c.device.conditional_rendering = (flags & kConditional) != 0;
    return c;
}

// Every mode (stereo two-pass, multiview, gs; hybrid with each culling variant; hybrid-farfield)
// x no AA / TAA / MSAA (stereo only) x SSAO off / per eye / stereo x the on/off inputs. Stereo
// ignores the culling variant and mono_skipped: they are varied in the hybrid modes only.
std::vector<Combination> all_combinations() {
    std::vector<Combination> all;
    for (Mode mode : {Mode::kStereo, Mode::kHybrid, Mode::kHybridFarfield}) {
        const bool hybrid = mode != Mode::kStereo;
        for (StereoPass pass :
             {StereoPass::kTwoPasses, StereoPass::kMultiview, StereoPass::kGeometryShader}) {
            for (MonoCulling culling :
                 {MonoCulling::kNoOpt, MonoCulling::kDiscard, MonoCulling::kOcclusionCull}) {
                if (!hybrid && culling != MonoCulling::kOcclusionCull) continue;
                for (AntiAliasing aa :
                     {AntiAliasing::kNone, AntiAliasing::kTaa, AntiAliasing::kMsaa4}) {
                    if (hybrid && aa == AntiAliasing::kMsaa4) continue;  // MSAA: stereo only
                    for (int ssao = 0; ssao < 3; ++ssao) {
                        for (unsigned flags = 0; flags < kFlagCount; ++flags) {
                            if (!hybrid && (flags & kMonoSkipped) != 0) continue;
                            all.push_back(combination(mode, pass, culling, aa, ssao, flags));
                        }
                    }
                }
            }
        }
    }
    return all;
}

const std::vector<Combination>& combinations() {
    static const std::vector<Combination> all = all_combinations();
    return all;
}

CompiledFrame compile_plan(const FramePlan& plan, const std::vector<ResourceState>& initial) {
    return graph::compile(plan.resources, plan.graph_passes(), plan.exports, initial);
}

std::vector<ResourceState> fresh_states(const FramePlan& plan) {
    return std::vector<ResourceState>(plan.resources.size());
}

// The plan as the checker replays it; with_predicates: each step of a pass the GPU predicates
// also reads the predicates in the conditional-rendering stage (VK_EXT_conditional_rendering
// reads them for every draw and dispatch inside the pass).
graph::Replay replay_of(const FramePlan& plan, bool with_predicates = false) {
    graph::Replay replay;
    replay.resources = &plan.resources;
    replay.exports = plan.exports;
    const std::optional<std::uint16_t> predicates =
        plan.handle({ViewId::kNone, true, ImageRole::kHdr, BufferRole::kPredicates});
    for (const PlannedPass& pass : plan.passes) {
        replay.names.push_back(pass.name);
        replay.runs.push_back(!pass.skipped.has_value());
        std::vector<graph::Step> steps = pass.steps;
        if (with_predicates && pass.when != GpuPredicate::kAlways && predicates) {
            for (graph::Step& step : steps) {
                step.uses.push_back({*predicates, graph::Use::kConditional});
            }
        }
        replay.steps.push_back(std::move(steps));
    }
    return replay;
}

std::uint16_t handle_of(const FramePlan& plan, ViewId view, ImageRole role) {
    const std::optional<std::uint16_t> handle =
        plan.handle({view, false, role, BufferRole::kDrawLists});
    if (!handle) throw std::logic_error("no resource " + resource_name({view, false, role}));
    return *handle;
}

// The next frame's initial states: this frame's final states, with each eye's history and
// history_previous swapped (the executor binds this frame's history as the next one's previous).
std::vector<ResourceState> next_frame_states(const FramePlan& plan,
                                             std::vector<ResourceState> states) {
    for (ViewId eye : kEyes) {
        const auto history = plan.handle({eye, false, ImageRole::kHistory});
        const auto previous = plan.handle({eye, false, ImageRole::kHistoryPrevious});
        if (history && previous) std::swap(states.at(*history), states.at(*previous));
    }
    return states;
}

// A barrier of a compiled frame and the pass whose step it precedes ("exports": the final ones).
struct Located {
    std::string pass;
    Barrier barrier;
};

std::vector<Located> barriers_on(const FramePlan& plan, const CompiledFrame& frame,
                                 std::uint16_t resource) {
    std::vector<Located> found;
    for (std::size_t p = 0; p < frame.steps.size(); ++p) {
        for (const graph::CompiledStep& step : frame.steps[p]) {
            for (const auto* list : {&step.before, &step.between_repeats}) {
                for (const Barrier& b : *list) {
                    if (b.resource == resource) found.push_back({plan.passes[p].name, b});
                }
            }
        }
    }
    for (const Barrier& b : frame.final_barriers) {
        if (b.resource == resource) found.push_back({"exports", b});
    }
    return found;
}

std::string listed(const Problems& problems) {
    std::string text;
    for (std::size_t i = 0; i < problems.size() && i < 8; ++i) text += "\n  " + problems[i];
    if (problems.size() > 8) text += "\n  ... " + std::to_string(problems.size() - 8) + " more";
    return text;
}

// Compiles every combination from nothing and, as the next frame, from the final states of a
// frame that drew the shadow map: compile refuses nothing (no pass reads what no pass or earlier
// frame produced) and the checker finds no hazard, no empty destination scope, and no empty
// source scope but a first use's transition from undefined.
TEST(PlanBarriers, EveryCombinationCompilesAndReplaysWithoutHazards) {
    for (const Combination& c : combinations()) {
        const FramePlan plan = plan_frame(c.options, c.frame, c.device);
        const graph::Replay replay = replay_of(plan);
        CompiledFrame first;
        ASSERT_NO_THROW(first = compile_plan(plan, fresh_states(plan))) << c.text();
        const Problems problems = graph::find_hazards(replay, first, fresh_states(plan));
        ASSERT_TRUE(problems.empty()) << c.text() << listed(problems);

        // The previous frame drew the shadow map (this one may reuse it).
        std::vector<ResourceState> initial = first.final_states;
        if (!c.frame.shadow_needed) {
            PlanFrame drawn = c.frame;
            drawn.shadow_needed = true;
            const FramePlan previous = plan_frame(c.options, drawn, c.device);
            ASSERT_EQ(previous.keys, plan.keys) << c.text();
            initial = compile_plan(previous, fresh_states(previous)).final_states;
        }
        initial = next_frame_states(plan, std::move(initial));
        CompiledFrame next;
        ASSERT_NO_THROW(next = compile_plan(plan, initial)) << c.text();
        const Problems next_problems = graph::find_hazards(replay, next, initial);
        ASSERT_TRUE(next_problems.empty()) << "next frame: " << c.text() << listed(next_problems);
    }
}

// A pass the GPU predicates (VK_EXT_conditional_rendering) reads the predicates for each of its
// draws and dispatches although its steps do not declare it: the predicates must already be
// visible to the conditional-rendering stage then.
TEST(PlanBarriers, PredicatedPassesFindThePredicatesVisible) {
    for (const Combination& c : combinations()) {
        if (!c.device.conditional_rendering) continue;
        const FramePlan plan = plan_frame(c.options, c.frame, c.device);
        const CompiledFrame frame = compile_plan(plan, fresh_states(plan));
        const Problems problems =
            graph::find_hazards(replay_of(plan, true), frame, fresh_states(plan));
        ASSERT_TRUE(problems.empty()) << c.text() << listed(problems);
    }
}

// C's HDR image, drawn (and blended by C's SSAO) as an attachment, is moved to shader-read-only
// once, before the first composite samples it; the second composite and C's tone mapping sample
// it in the same stage and layout and need nothing.
void expect_mono_hdr_transitioned_once(const FramePlan& plan, const CompiledFrame& frame,
                                       const std::string& context) {
    const std::uint16_t hdr = handle_of(plan, ViewId::kMono, ImageRole::kHdr);
    std::vector<Located> to_sampled;
    for (const Located& at : barriers_on(plan, frame, hdr)) {
        EXPECT_NE(at.pass, "right.composite") << context;
        EXPECT_NE(at.pass, "mono.tonemap") << context;
        if (at.barrier.new_layout == Layout::kShaderReadOnly) to_sampled.push_back(at);
    }
    ASSERT_EQ(to_sampled.size(), 1u) << context;
    EXPECT_EQ(to_sampled[0].pass, "left.composite") << context;
    EXPECT_EQ(to_sampled[0].barrier,
              (Barrier{hdr, Stage::kColorAttachmentOutput, Access::kColorAttachmentWrite,
                       Stage::kFragmentShader, Access::kShaderSampledRead, Layout::kColorAttachment,
                       Layout::kShaderReadOnly}))
        << context;
}

TEST(PlanBarriers, MonoHdrIsTransitionedOnceBeforeTheFirstComposite) {
    for (const Combination& c : combinations()) {
        if (!c.draws_mono()) continue;
        const FramePlan plan = plan_frame(c.options, c.frame, c.device);
        const CompiledFrame first = compile_plan(plan, fresh_states(plan));
        expect_mono_hdr_transitioned_once(plan, first, c.text());
        const std::vector<ResourceState> initial = next_frame_states(plan, first.final_states);
        expect_mono_hdr_transitioned_once(plan, compile_plan(plan, initial), "next: " + c.text());
        if (HasFailure()) return;
    }
}

// Each eye's depth attachment is sampled by the pyramid's compute shader in depth-read-only and
// tested by its composite as an attachment again; without a pyramid it never leaves the
// attachment layout, and the composite's test waits for the forward pass's depth writes.
void expect_eye_depth_barriers(const Combination& c, const FramePlan& plan,
                               const CompiledFrame& frame) {
    constexpr Access kDepthWrite = Access::kDepthStencilAttachmentWrite;
    constexpr Access kDepthRead = Access::kDepthStencilAttachmentRead;
    for (ViewId eye : kEyes) {
        const std::uint16_t depth = handle_of(plan, eye, ImageRole::kDepth);
        const std::string composite = view_name(eye) + ".composite";
        std::map<std::string, std::vector<Barrier>> by_pass;
        for (const Located& at : barriers_on(plan, frame, depth))
            by_pass[at.pass].push_back(at.barrier);
        if (c.pyramid()) {
            EXPECT_EQ(by_pass["depth_pyramid"],
                      (std::vector<Barrier>{{depth, kDepthTests, kDepthWrite, Stage::kComputeShader,
                                             Access::kShaderSampledRead, Layout::kDepthAttachment,
                                             Layout::kDepthReadOnly}}))
                << c.text();
            // Back after the compute reads (the first write was made available before them).
            EXPECT_EQ(by_pass[composite],
                      (std::vector<Barrier>{{depth, Stage::kComputeShader, Access::kNone,
                                             kDepthTests, kDepthRead, Layout::kDepthReadOnly,
                                             Layout::kDepthAttachment}}))
                << c.text();
        } else {
            EXPECT_EQ(by_pass.count("depth_pyramid"), 0u) << c.text();
            EXPECT_EQ(
                by_pass[composite],
                (std::vector<Barrier>{{depth, kDepthTests, kDepthWrite, kDepthTests, kDepthRead,
                                       Layout::kDepthAttachment, Layout::kDepthAttachment}}))
                << c.text();
        }
    }
}

TEST(PlanBarriers, EachEyesDepthGoesReadOnlyForThePyramidAndBackForItsComposite) {
    for (const Combination& c : combinations()) {
        const FramePlan plan = plan_frame(c.options, c.frame, c.device);
        const CompiledFrame frame = compile_plan(plan, fresh_states(plan));
        if (c.draws_mono()) {
            expect_eye_depth_barriers(c, plan, frame);
        } else {
            // Stereo's eye depth (absent with MSAA: the samples' depth is drawn instead) stays an
            // attachment.
            for (ViewId eye : kEyes) {
                const auto depth = plan.handle({eye, false, ImageRole::kDepth});
                if (!depth) continue;
                for (const Located& at : barriers_on(plan, frame, *depth)) {
                    EXPECT_EQ(at.barrier.new_layout, Layout::kDepthAttachment) << c.text();
                }
            }
        }
        if (HasFailure()) return;
    }
}

// TAA reads history_previous (the previous frame's resolve) in the step that writes history, and
// nothing of the frame writes history_previous. The first frame has no previous resolve: its read
// is a first use from undefined. From then on the executor swaps the two images every frame: the
// image read as history_previous was left sampled by the previous frame's tone mapping (fragment
// shader, shader-read-only) and needs no barrier, never a transition from undefined; the image
// written as history waits for those reads.
void expect_taa_frames(const Combination& c, const FramePlan& plan) {
    const CompiledFrame first = compile_plan(plan, fresh_states(plan));
    const CompiledFrame second = compile_plan(plan, next_frame_states(plan, first.final_states));
    const CompiledFrame third = compile_plan(plan, next_frame_states(plan, second.final_states));
    for (ViewId eye : kEyes) {
        const std::uint16_t previous = handle_of(plan, eye, ImageRole::kHistoryPrevious);
        const std::uint16_t history = handle_of(plan, eye, ImageRole::kHistory);
        const std::string taa =
            view_name(eye) + ".taa";  // the pass's name, as barriers_on gives it
        EXPECT_EQ(plan.reads(*plan.find(PassKind::kTaa, eye)),
                  (std::vector<std::string>{view_name(eye) + ".hdr", view_name(eye) + ".velocity",
                                            view_name(eye) + ".linear_depth",
                                            view_name(eye) + ".history_previous"}))
            << c.text();
        for (const PlannedPass& pass : plan.passes) {
            const std::vector<std::string> writes = plan.writes(pass);
            EXPECT_EQ(
                std::count(writes.begin(), writes.end(), view_name(eye) + ".history_previous"), 0)
                << c.text() << ": " << pass.name;
        }
        const std::vector<Located> at_first = barriers_on(plan, first, previous);
        ASSERT_EQ(at_first.size(), 1u) << c.text();
        EXPECT_EQ(at_first[0].pass, taa) << c.text();
        EXPECT_EQ(at_first[0].barrier, (Barrier{previous, Stage::kNone, Access::kNone,
                                                Stage::kFragmentShader, Access::kShaderSampledRead,
                                                Layout::kUndefined, Layout::kShaderReadOnly}))
            << c.text();
        EXPECT_TRUE(barriers_on(plan, second, previous).empty()) << c.text();
        const std::vector<Located> written = barriers_on(plan, second, history);
        ASSERT_FALSE(written.empty()) << c.text();
        EXPECT_EQ(written[0].pass, taa) << c.text();
        EXPECT_TRUE(graph::covers(written[0].barrier.src_stages, Stage::kFragmentShader))
            << c.text();
        EXPECT_EQ(written[0].barrier.dst_stages, Stage::kColorAttachmentOutput) << c.text();
        EXPECT_EQ(written[0].barrier.new_layout, Layout::kColorAttachment) << c.text();
    }
    // The ping-pong is steady from the second frame on.
    EXPECT_EQ(third.steps.size(), second.steps.size());
    for (std::size_t p = 0; p < second.steps.size(); ++p) {
        for (std::size_t s = 0; s < second.steps[p].size(); ++s) {
            EXPECT_EQ(third.steps[p][s].before, second.steps[p][s].before)
                << c.text() << ": " << plan.passes[p].name;
        }
    }
}

TEST(PlanBarriers, TaaReadsHistoryPreviousBeforeWritingHistoryAndNeverFromUndefinedAfterward) {
    for (const Combination& c : combinations()) {
        if (c.options.anti_aliasing != AntiAliasing::kTaa) continue;
        expect_taa_frames(c, plan_frame(c.options, c.frame, c.device));
        if (HasFailure()) return;
    }
}

// Deletes each barrier of a compiled frame in turn: the checker must find a hazard every time.
void expect_every_barrier_needed(const FramePlan& plan, const std::vector<ResourceState>& initial,
                                 const std::string& context) {
    const graph::Replay replay = replay_of(plan);
    const CompiledFrame frame = compile_plan(plan, initial);
    ASSERT_TRUE(graph::find_hazards(replay, frame, initial).empty()) << context;
    CompiledFrame copy = frame;
    std::vector<std::vector<Barrier>*> lists;
    for (auto& pass : copy.steps) {
        for (graph::CompiledStep& step : pass) {
            lists.push_back(&step.before);
            lists.push_back(&step.between_repeats);
        }
    }
    lists.push_back(&copy.final_barriers);
    for (std::vector<Barrier>* list : lists) {
        for (std::size_t i = 0; i < list->size(); ++i) {
            const Barrier deleted = (*list)[i];
            list->erase(list->begin() + static_cast<std::ptrdiff_t>(i));
            EXPECT_FALSE(graph::find_hazards(replay, copy, initial).empty())
                << context << ": without " << graph::describe(deleted, plan.resources);
            list->insert(list->begin() + static_cast<std::ptrdiff_t>(i), deleted);
        }
    }
}

// Deleting any one barrier of a compiled frame (a first frame, and the next one from its final
// states) leaves a hazard the checker finds: the checker can fail, and no barrier the compile
// step places is superfluous. Over a sample of the combinations (every 61st, which goes through
// every mode, culling variant, AA and SSAO setting; all of them take 50 s and pass too).
TEST(HazardChecker, FindsAHazardWhenAnyOneBarrierOfACompiledFrameIsDeleted) {
    constexpr std::size_t kStride = 61;
    const std::vector<Combination>& all = combinations();
    for (std::size_t i = 0; i < all.size(); i += kStride) {
        const Combination& c = all[i];
        const FramePlan plan = plan_frame(c.options, c.frame, c.device);
        const std::vector<ResourceState> fresh = fresh_states(plan);
        expect_every_barrier_needed(plan, fresh, c.text());
        const std::vector<ResourceState> next =
            next_frame_states(plan, compile_plan(plan, fresh).final_states);
        expect_every_barrier_needed(plan, next, "next frame: " + c.text());
        if (HasFailure()) return;
    }
}

// The one barrier the composites need on C's image, deleted: the first composite samples an image
// still in the attachment layout, with the write neither waited for nor visible.
TEST(HazardChecker, ReportsTheCompositeSamplingMonoHdrWithoutItsBarrier) {
    const FramePlan plan =
        plan_frame(PlanOptions{.mode = Mode::kHybrid}, PlanFrame{}, PlanDevice{});
    const std::vector<ResourceState> fresh = fresh_states(plan);
    CompiledFrame frame = compile_plan(plan, fresh);
    const std::uint16_t hdr = handle_of(plan, ViewId::kMono, ImageRole::kHdr);
    std::size_t composite = 0;
    while (plan.passes.at(composite).name != "left.composite") ++composite;
    std::vector<Barrier>& before = frame.steps.at(composite).at(0).before;
    const auto removed = std::erase_if(before, [&](const Barrier& b) { return b.resource == hdr; });
    ASSERT_EQ(removed, 1u);
    const Problems problems = graph::find_hazards(replay_of(plan), frame, fresh);
    ASSERT_FALSE(problems.empty());
    EXPECT_EQ(problems[0],
              "left.composite/composite: mono.hdr used in shader-read-only while it is in "
              "color-attachment")
        << listed(problems);
}

// Without a read-back nothing reads C's tone-mapped image: the culling drops mono.tonemap, and
// nothing else, in any combination (every other pass's output is read or exported).
TEST(PlanCulling, OnlyHybridsMonoTonemapWithoutReadBackIsCulled) {
    for (const Combination& c : combinations()) {
        const FramePlan plan = plan_frame(c.options, c.frame, c.device);
        std::map<std::string, std::string> culled;
        for (const PlannedPass& pass : plan.passes) {
            if (pass.skipped && pass.skipped->starts_with("culled:"))
                culled[pass.name] = *pass.skipped;
        }
        std::map<std::string, std::string> expected;
        if (c.draws_mono() && !c.options.read_back) {
            expected["mono.tonemap"] = "culled: nothing reads mono.display";
        }
        ASSERT_EQ(culled, expected) << c.text();
    }
}

TEST(PlanCulling, MonoTonemapRunsWithReadBack) {
    for (bool conditional : {false, true}) {
        PlanOptions options;
        options.mode = Mode::kHybrid;
        options.read_back = true;
        const FramePlan plan = plan_frame(options, PlanFrame{}, PlanDevice{conditional});
        const PlannedPass* tonemap = plan.find(PassKind::kTonemap, ViewId::kMono);
        ASSERT_NE(tonemap, nullptr);
        EXPECT_FALSE(tonemap->skipped.has_value()) << *tonemap->skipped;
        const std::vector<std::string> reads = plan.reads(*plan.find(PassKind::kReadback));
        EXPECT_NE(std::find(reads.begin(), reads.end(), "mono.display"), reads.end());
        options.read_back = false;
        const FramePlan unread = plan_frame(options, PlanFrame{}, PlanDevice{conditional});
        const PlannedPass* unread_tonemap = unread.find(PassKind::kTonemap, ViewId::kMono);
        ASSERT_NE(unread_tonemap, nullptr);
        EXPECT_EQ(unread_tonemap->skipped, "culled: nothing reads mono.display");
    }
}

}  // namespace
}  // namespace monoplane::plan
