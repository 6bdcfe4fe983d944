// The render graph's core: a frame's resources as typed handles, its passes as steps that declare
// how they use them, and the compile step that turns those uses into the frame's barriers (layout
// transitions and memory dependencies, as synchronization2 would record them) and its final
// states. Culling from the dataflow drops a pass whose outputs nothing reads.
//
// The model: each resource has a state (layout, the last write's stages and accesses, where that
// write has been made visible, the stages that read it since). A use that writes waits for the
// last write and every read since (write-after-write, write-after-read); a use that reads waits
// for the last write unless an earlier barrier already made it visible to the reader's stages and
// accesses; a use in another layout transitions the image. The executor (renderer/modes) applies
// the barriers before each step and keeps each physical image's state from frame to frame, so the
// first barrier of a frame orders it after the previous frames' accesses (frames in flight).
//
// Aliasing (transient_aliasing.h): resources may share memory with others. The first use in a
// frame of one that takes the memory over from another (used earlier in the frame, or last in the
// previous one) waits for that one's accesses and transitions from the undefined layout: its own
// earlier contents and layout are gone.
//
// Refusals (programming errors in the plan, common/programming_error.h; never a user's input):
// a transient resource read before any step of the frame wrote it; one step using a resource in
// two layouts; a buffer-only use (indirect, conditional, host) of an image; an image-only use
// (attachment, transfer of layouts) of a buffer is allowed only for transfer and storage uses;
// a persistent or exported resource that shares memory, and two resources sharing memory whose
// uses interleave.
//
// When may this be called: any time; pure, no device.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "renderer/graph/resource_use.h"
#include "renderer/graph/sync_scope.h"

namespace monoplane::graph {

enum class ResourceKind : std::uint8_t { kImage, kBuffer };

enum class Lifetime : std::uint8_t {
    // Written each frame before anything reads it; earlier frames' contents are not needed.
    kTransient,
    // Carried from frame to frame: may be read before this frame writes it (the previous frame's
    // version: TAA's history, a shadow map kept while the light's region holds, AO images
    // initialised at creation). A write to one is an output of the frame (never culled).
    kPersistent,
};

// Typed handles: an image handle cannot name a buffer. The index is the resource's place in the
// graph's table; handles of one graph mean nothing in another.
struct ImageHandle {
    std::uint16_t index = 0;
    bool operator==(const ImageHandle&) const = default;
};
struct BufferHandle {
    std::uint16_t index = 0;
    bool operator==(const BufferHandle&) const = default;
};

struct ResourceDesc {
    std::string name;  // for messages and `render --json`: "left.hdr", "draw_lists", ...
    ResourceKind kind = ResourceKind::kImage;
    Lifetime lifetime = Lifetime::kTransient;
};

struct ResourceUse {
    std::uint16_t resource = 0;  // the handle's index
    Use use = Use::kSampledFragment;
    bool operator==(const ResourceUse&) const = default;
};

// One step of a pass: what it records between two points where barriers may be needed (a render
// pass instance, a dispatch, a copy). Most passes have one step; SSAO and the pyramid have several.
struct Step {
    std::string name;
    std::vector<ResourceUse> uses;
    // Recorded several times in a row (the pyramid's reduction, one dispatch per level): each
    // recording after the first waits for the one before.
    bool repeats = false;
};

class ResourceTable {
  public:
    ImageHandle image(std::string name, Lifetime lifetime = Lifetime::kTransient);
    BufferHandle buffer(std::string name, Lifetime lifetime = Lifetime::kTransient);
    const ResourceDesc& operator[](std::uint16_t index) const { return resources_.at(index); }
    std::size_t size() const { return resources_.size(); }
    // The handle of that name, or nullopt.
    std::optional<std::uint16_t> find(const std::string& name) const;

  private:
    std::vector<ResourceDesc> resources_;
};

// Builds a step's uses with typed handles.
class StepBuilder {
  public:
    explicit StepBuilder(Step& step) : step_(step) {}
    StepBuilder& use(ImageHandle image, Use use);
    StepBuilder& use(BufferHandle buffer, Use use);

  private:
    Step& step_;
};

struct ResourceState {
    Layout layout = Layout::kUndefined;
    Stage write_stages = Stage::kNone;  // the last write (or layout transition), if any
    Access write_access = Access::kNone;
    Stage visible_stages = Stage::kNone;  // where the last write has been made visible
    Access visible_access = Access::kNone;
    Stage read_stages = Stage::kNone;  // reads since the last write
    bool operator==(const ResourceState&) const = default;
};

struct Barrier {
    std::uint16_t resource = 0;
    Stage src_stages = Stage::kNone;
    Access src_access = Access::kNone;
    Stage dst_stages = Stage::kNone;
    Access dst_access = Access::kNone;
    Layout old_layout = Layout::kUndefined;  // images: equal to new_layout when nothing changes
    Layout new_layout = Layout::kUndefined;
    // The resource takes over memory another one held: the source is that one's accesses.
    bool aliasing = false;
    bool operator==(const Barrier&) const = default;
};
// "left.hdr: color-attachment-output/color-attachment-write -> fragment-shader/shader-sampled-read,
// color-attachment -> shader-read-only": for tests' messages and `render --json`.
std::string describe(const Barrier& barrier, const ResourceTable& resources);

// A pass as the compile step sees it: its steps, and whether it runs.
struct GraphPass {
    std::string name;
    const std::vector<Step>* steps = nullptr;
    bool runs = true;  // false: skipped by the plan or culled; contributes nothing
};

struct CompiledStep {
    std::vector<Barrier> before;           // before the step's first recording
    std::vector<Barrier> between_repeats;  // before each later recording (Step::repeats)
};

// Memory that several resources share (transient_aliasing.h), as the frame begins: which resource
// used it last.
struct MemoryHolder {
    // That resource's index in this frame's table, or -1: none, or one this frame's table lacks
    // (a resource of another plan), whose final state is then `state`.
    std::int32_t resource = -1;
    ResourceState state;
    bool operator==(const MemoryHolder&) const = default;
};

struct Aliasing {
    std::vector<std::int32_t> memory;   // per resource: the shared memory it is bound to, or -1
    std::vector<MemoryHolder> initial;  // per shared memory
    bool operator==(const Aliasing&) const = default;
};

struct CompiledFrame {
    // steps[p][s]: step s of pass p (no steps for passes that do not run).
    std::vector<std::vector<CompiledStep>> steps;
    // After the last pass: what makes the frame's exports (host reads, images handed on) ready.
    std::vector<Barrier> final_barriers;
    // Every resource's state after the frame: the next frame's initial state.
    std::vector<ResourceState> final_states;
    // Per shared memory (Aliasing::initial): the resource that used it last (-1 as there).
    std::vector<std::int32_t> final_holders;
};

// initial_states: one per resource (the previous frame's final state of the physical resource
// now bound to it; default-constructed for one never used). exports: uses after the last pass
// (read-backs by the host, images another component reads next). aliasing: empty, or which
// resources share memory and who held each memory before the frame.
CompiledFrame compile(const ResourceTable& resources, const std::vector<GraphPass>& passes,
                      const std::vector<ResourceUse>& exports,
                      const std::vector<ResourceState>& initial_states,
                      const Aliasing& aliasing = {});

// Culling from the dataflow: for each pass, whether something needs it: it writes a resource an
// export, a persistent resource or a later needed pass reads. Passes with runs == false are
// ignored (they produce nothing). A pass with no writes at all is never needed.
std::vector<bool> needed_passes(const ResourceTable& resources,
                                const std::vector<GraphPass>& passes,
                                const std::vector<ResourceUse>& exports);

}  // namespace monoplane::graph
