// The render graph's executor: compiles each frame's plan (renderer/plan/frame_plan.h) against
// the states the device objects were left in, records the compiled barriers before each step, and
// keeps every image's and buffer's state from frame to frame, so a frame's first barrier on an
// object waits for the accesses of the frames before it (frames in flight). The one place in the
// renderer that records pipeline barriers and layout transitions for a frame.
//
// When may this be called: begin_frame once per frame before its passes, begin_pass before each
// pass that runs (in the plan's order), end_frame after the last; from the thread that records.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "renderer/graph/frame_graph.h"
#include "renderer/passes/shared/step_sync.h"
#include "renderer/plan/frame_plan.h"
#include "renderer/vk/image.h"

namespace monoplane::executor {

// What one of the plan's resources is on the device this frame: its images (several for SSAO's
// scratch images, one layer of a two-layer image for an eye of single-pass stereo), or nothing
// for a buffer (buffers are synchronised with memory barriers) and for a resource only passes the
// frame leaves out use.
struct BoundResource {
    std::vector<vk_core::ImageRange> images;
    // An image shared by several renderers (the scene's shadow map) keeps its state with it, so
    // each renderer's frames start from what the last one, of any renderer, left.
    graph::ResourceState* shared_state = nullptr;
};

class GraphExecutor {
  public:
    GraphExecutor();
    ~GraphExecutor();
    GraphExecutor(const GraphExecutor&) = delete;
    GraphExecutor& operator=(const GraphExecutor&) = delete;

    // Compiles the frame (or reuses the last compilation: same plan, same initial states).
    // bindings[r]: resource r of plan.resources.
    void begin_frame(const plan::FramePlan& plan, std::vector<BoundResource> bindings);
    // The plan passed to begin_frame is a new one (its owner remade it): compile it afresh.
    void plan_changed() { ++plan_generation_; }
    // Records the first step's barriers of plan.passes[pass] (a pass of one step), and returns
    // the sync a pass of several steps calls before each of its steps.
    passes::StepSync& begin_pass(const vk::raii::CommandBuffer& cmd, std::size_t pass);
    // Checks the pass recorded every step it declared.
    void end_pass();
    // The barriers that make the frame's exports ready (read-backs for the host, display images
    // for a headset's swapchain).
    void end_frame(const vk::raii::CommandBuffer& cmd);

    // The layout an image was left in by the last frame recorded (its initial layout if no frame
    // used it).
    vk::ImageLayout layout_of(const vk_core::ImageRange& image) const;
    // Before an image is destroyed: its state must not pass to a new image with the same handle.
    void forget(const vk_core::ImageRange& image);

    // Tests only: drops the compiled barriers for which `drop` returns true (to show that the
    // synchronisation validation layer reports the hazard left behind). A barrier that changes an
    // image's layout keeps its transition with nothing before it to wait for, so that the layer
    // reports the missing dependency rather than an image in the wrong layout.
    using BarrierFilter = std::function<bool(const graph::Barrier&, const plan::FramePlan&)>;
    void drop_barriers_for_test(BarrierFilter drop) { drop_ = std::move(drop); }

  private:
    class PassSync;
    using ImageId = std::pair<VkImage, std::uint32_t>;  // an image and its base layer

    void record(const vk::raii::CommandBuffer& cmd, const std::vector<graph::Barrier>& barriers);
    std::vector<graph::ResourceState> initial_states() const;
    // Which of this frame's resources share memory (vk_core::ImageRange::shared_memory), and
    // which image used each memory last.
    graph::Aliasing aliasing();
    void keep_final_states(const std::vector<graph::ResourceState>& states);

    const plan::FramePlan* plan_ = nullptr;
    std::vector<BoundResource> bindings_;
    graph::CompiledFrame compiled_;
    // What compiled_ was made from: the plan's generation and the initial states.
    std::uint64_t plan_generation_ = 1;
    std::uint64_t compiled_generation_ = 0;
    std::vector<graph::ResourceState> compiled_initial_;
    graph::Aliasing compiled_aliasing_;
    std::vector<vk::DeviceMemory> memories_;            // this frame's, Aliasing's order
    std::map<VkDeviceMemory, ImageId> memory_holders_;  // the image that used it last
    std::map<ImageId, graph::ResourceState> image_states_;
    std::map<std::string, graph::ResourceState> buffer_states_;  // by the resource's name
    std::unique_ptr<PassSync> sync_;
    BarrierFilter drop_;
};

}  // namespace monoplane::executor
